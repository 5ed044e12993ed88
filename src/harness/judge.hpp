#pragma once
// How the random scenes' harness judges a method's airlight image against the
// reference's (docs/design.md §6): every method at its defaults, then each of
// its own trials (MethodInfo::trials) by their measure and bound.
#include <airlight/image.hpp>
#include <airlight/method.hpp>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <string>
#include <vector>

namespace airlight::harness {

// W/(m²·sr). Below it a reference is black: rRMSE divides by at least this, and
// a pixel under it is never judged by its relative error. The generator scales
// its lights so that airlight is of order 1 (harness/random_scene.cpp), so this
// is a millionth of a typical image.
inline constexpr double absolute_floor = 1e-6;

// A configuration whose reference's mean airlight is below this is rejected as
// invisible: 1/1000 of the order the generator aims at, about 1 % of 8-bit
// display white at exposure 1 after the sRGB curve — fog no one would see.
inline constexpr double visible_mean = 1e-3;

// What every method must meet at its defaults: a map-based method at its
// default settings is held to 10 % (issue 25), far above the quality table's
// rows, so that only a defect fails it.
inline constexpr double default_rel_rmse = 0.10;

// The share of the image's maximum above which worst_pixel judges a pixel.
inline constexpr double judged_share = 0.01;

// The reference's value at each pixel, bracketed. A rasterizer samples a pixel
// on a grid of 1/256 pixel (8 subpixel bits, llvmpipe and GPUs alike) and a
// method rebuilds its view ray in float, so where so small a shift changes the
// value — a silhouette, a light's image — a method may rightly give anything
// the pixel holds near its centre. `centre` is the reference through the
// pixel's centre; `low` and `high` the least and greatest per channel of it,
// of four rays bracket_shift beside it (twice that grid) and of its own ray
// with the near plane moved by ±near_margin. A method's error
// at a pixel is its distance outside [low, high]; its scale is `centre`, or
// the value in [low, high] nearest the method's where that is larger: beside
// a light's image a pixel may rightly hold 70 times its centre, and 0.2 %
// past that was 13 % of the centre (random scene 314).
inline constexpr double bracket_shift = 1.0 / 128.0;
// The near plane moved either way by near_margin: a rasterizer transforms
// world coordinates as large as the eye's in float, so a surface within a few
// of their ulps of the near plane may be clipped or kept (random scene 206: a
// polyhedron's corner 6 µm from an eye 1 m from the origin, the near plane
// 5.6 µm, its faces 0.02–0.14 µm past it; the reference kept them, every GPU
// method clipped them at scattered pixels). 2⁻²⁰ of the eye's distance from
// the origin is 16 ulps of its coordinates.
inline double near_margin(const Camera& camera) { return 0x1p-20 * glm::length(glm::dvec3(camera.position)); }
struct Reference {
  Image centre, low, high;
};
// `images`: the centre's first, then those shifted (reference::Settings::subpixel).
Reference bracket(const std::vector<Image>& images);
// The pixels where a shift of bracket_shift may matter: some neighbour's value
// (largest channel) differs from the pixel's by more than bracket_sharpness of
// it. Elsewhere the value varies smoothly, and a 1/128-pixel shift changes it
// by about 1/128 of a neighbour's difference, under 0.02 % of the pixel: the
// shifted rays are traced only at these (reference::Settings::pixels). Below
// the exact methods' 2 %: a silhouette in one light's share, the other lights'
// smooth shares added, may differ from its neighbour by less than the error it
// can cause (random scene 257: a sun's share jumping 11 % at a surface's edge
// was 4.4 % of the pixel and 8.7 % from its neighbour, under the 1/8 this was).
inline constexpr double bracket_sharpness = 1.0 / 64.0;
std::vector<bool> sharp_pixels(const Image& centre);
// A reference known exactly at each pixel (hand-made images, tests).
inline Reference exactly(const Image& image) { return {image, image, image}; }
// The bracket widened to hold `other` too (Trial::baseline): a pixel between
// the two answers is right by either.
Reference widened(Reference reference, const Image& other);

struct Verdict {
  std::string trial;    // "defaults" or the trial's name
  std::string measure;  // "rel_rmse", "worst_pixel", "finite", "zero"
  double value = 0.0, bound = 0.0;
  bool pass = false;
  std::string detail;   // why it failed, in words: "pixel (3, 7) is NaN", "pixel (12, 4): 0.31 against 0.25"
};

// The mean over pixels and channels.
double mean(const Image& image);
// Whether the harness judges methods on `scene` whose reference is `reference`:
// a scene without lights always (every method must give zero), any other when
// its fog is visible (mean ≥ visible_mean).
bool judged(const Scene& scene, const Image& reference);

double rel_rmse(const Image& method, const Reference& reference);
// The largest relative error among the pixels whose largest reference channel
// reaches judged_share of the image's maximum (and absolute_floor); its pixel.
struct WorstPixel {
  double error = 0.0;
  int x = -1, y = -1;
};
WorstPixel worst_pixel(const Image& method, const Reference& reference);

// The image has a NaN, an infinity or a negative value: what and where, else empty.
std::string bad_value(const Image& image);

// The reference against brute force (reference/brute_force.hpp) at a few
// pixels: the largest channel error over the largest brute-force channel, each
// pixel's denominator at least reference_floor of the image's maximum. 2e-3:
// the reference integrates each light to a relative 1e-3 (its rel_tol) on float
// rays; the brute force is good to 1e-9, so twice that is a fault, not noise.
inline constexpr double reference_bound = 2e-3;
inline constexpr double reference_floor = 1e-3;
Verdict judge_reference(const Image& reference, const std::vector<glm::ivec2>& pixels,
                        const std::vector<glm::dvec3>& brute_force);

// At the defaults: finite and non-negative, and either zero where the
// reference is (a scene without lights) or within default_rel_rmse.
Verdict judge_defaults(const Image& method, const Reference& reference);
// A trial: finite and non-negative, then its measure within its bound.
Verdict judge_trial(const Trial& trial, const Image& method, const Reference& reference);

}  // namespace airlight::harness
