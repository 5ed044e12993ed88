#pragma once
// The airlight integral of docs/design.md §1 for one light along a ray segment, by
// adaptive quadrature: the single source of truth every method is judged by.
#include <airlight/scene.hpp>
#include <functional>
#include <glm/vec3.hpp>

namespace airlight::optics {

struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 dir{0, 0, -1};  // unit
};

// V(x): is the light visible from the point x? (true = lit)
using Visibility = std::function<bool(const glm::dvec3& x)>;

// The integrand e(x) without visibility: σs·p(cos θ)·I(ω)·exp(-τ_light)/r² · exp(-τ_eye(x)),
// radiance per metre toward the ray's origin from distance x along it.
glm::dvec3 inscatter(const Scene& scene, const Light& light, const Ray& ray, double x);

struct QuadratureSettings {
  double rel_tol = 1e-4;   // target of the summed |K15 - G7| error estimates,
                           // relative to the whole integral, per channel
  int min_segments = 32;   // initial split: visibility features narrower than
                           // (t1 - t0) / min_segments may be missed
  int max_depth = 30;      // bisections of an initial panel
};

// ∫_{t0}^{t1} V(x)·e(x) dx per channel (t1 finite; 0 if t1 <= t0). The integral
// runs over the part where the light reaches only: inside a beam's box
// (beam_interval, light.hpp) or inside a spot's cone (cone_intervals, light.hpp),
// so that no panel straddles the faces where e jumps and the min_segments panels
// spread over lit ground, not over the whole ray (a lit sliver between a panel's
// nodes would be missed). Panels break at volume crossings, at the ends of the
// parts inside the spot's inner-edge cone, at the foot of the perpendicular from
// a point or spot light with geometric grading around it (1/r² peaks there), and
// into min_segments even panels; then globally adaptive G7K15 in double
// precision. V is probed at each panel's nodes and ends; where it differs
// between neighbouring probes, the boundary is bisected to 1e-6·(t1 - t0) and
// each side integrated separately.
// V may be empty (always lit). Through a light, r is clamped at
// min_light_distance (light.hpp), so the result is finite (never NaN/Inf).
glm::dvec3 airlight_quadrature(const Scene& scene, const Light& light, const Ray& ray,
                               double t0, double t1, const Visibility& visible,
                               const QuadratureSettings& settings = {});

}  // namespace airlight::optics
