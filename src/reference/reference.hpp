#pragma once
// The CPU ground truth (docs/design.md §3 `reference`): exact visibility by Embree ray
// casts, the airlight integral of docs/design.md §1 by optics::airlight_quadrature, and
// Lambertian surfaces, per pixel of the camera of docs/design.md §5. Every method is judged
// against its airlight image.
#include <airlight/error.hpp>
#include <airlight/image.hpp>
#include <airlight/scene.hpp>
#include <atomic>
#include <vector>

#include <glm/vec2.hpp>

namespace airlight::reference {

struct Settings {
  double rel_tol = 1e-3;  // of each light's airlight integral along each view ray
  // Initial split of each view ray: narrower lit or dark stretches may be missed.
  // 128 keeps every built-in within 3e-4 of brute force at 64×48, where 32 lost
  // whole lit gaps (docs/decisions.md "The reference checked by brute force").
  int min_segments = 128;
  // Where in each pixel its ray passes, in pixels from its corner: the centre,
  // as a rasterizer samples. The random scenes' harness moves it to bracket the
  // pixel's value where a subpixel shift changes it (an edge, a light's image).
  glm::dvec2 subpixel{0.5, 0.5};
  // Which pixels to render, row by row (the rest are left 0); empty: all.
  std::vector<bool> pixels{};
  // Moves the near plane this far along each view ray (a surface counts from
  // near + near_shift on, never before the eye): the random scenes' harness
  // brackets a pixel whose visible surface lies within a rasterizer's rounding
  // of the near plane.
  double near_shift = 0.0;
  // false: the surface alone, airlight left 0 (tests of a method's surface pass,
  // where the airlight's integral is nearly all of the time).
  bool airlight = true;
};

struct Images {
  Image airlight;   // L_air = Σ_lights ∫_0^d σs·p·I·V·T_light/r²·T_eye dx    (docs/design.md §1)
  Image surface;    // L_surf · T(d); 0 where the view ray reaches the far plane
  Image composite;  // surface + airlight
  long shadow_rays = 0;  // occlusion rays traced (for shadow rays per second)
  long nonfinite = 0;    // pixel channels that were NaN or overflowed float and were
                         // replaced (NaN → 0, +∞ → FLT_MAX); 0 unless a light sits on a view ray
};

// Lets another thread follow a render and stop it (the viewer's background
// reference): `done` of `total` tiles are finished; once `cancel` is set the
// tiles not yet started are skipped and render throws Cancelled.
struct Control {
  std::atomic<bool> cancel{false};
  std::atomic<long> done{0}, total{0};
};
struct Cancelled : Failure {
  Cancelled() : Failure("reference: cancelled") {}
};

// Renders all three passes of `scene` at width × height. Shows progress on
// stderr when it is a terminal. Throws airlight::Failure on Embree errors.
Images render(const Scene& scene, int width, int height, const Settings& settings = {}, Control* control = nullptr);

}  // namespace airlight::reference
