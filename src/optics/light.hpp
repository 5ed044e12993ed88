#pragma once
// What a light sends toward a point: radiant intensity I(ω) of point and spot
// lights (cone, smooth edge, gobo), a directional light's beam (bounded box,
// gobo across its aperture), and the distance attenuation of each light model.
#include <airlight/scene.hpp>
#include <array>
#include <numbers>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "optics/slab.hpp"

namespace airlight::optics {

inline double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Spot cone factor in [0, 1] for the angle between the axis and `dir` (unit,
// from the light): 1 inside cone_deg - edge_deg, smoothstep down to 0 at cone_deg.
double spot_cone(const Light& light, const glm::dvec3& dir);

// The part of the segment [t0, t1] of the line origin + t·dir inside the cone
// of apex `apex`, unit `axis` and half-angle `half_angle` (radians): the points x
// with angle(axis, x - apex) <= half_angle, the lit set of spot_cone's hard cut
// (Nilsson §2.5, eq. 2.9: "determine the interval on the eye ray that is inside
// the cone", by the line–cone intersection of Eberly [22] there). One-sided:
// the backward nappe is dark; from half_angle > π/2 on, the lit set is the
// complement of the backward cone of half-angle π - half_angle, and a line may
// cross that dark cone, leaving two pieces. `dir` is unit. Pieces have positive
// length and come in ascending order; isolated points (a tangent line, a line
// through the apex outside the cone) are dropped. Degenerate lines are handled
// without thresholds: along the axis, through the apex, parallel to a
// generator, half_angle = π/2 (a half-space) or >= π (all of space).
struct ConeIntervals {
  int count = 0;                      // 0, 1 or 2
  std::array<glm::dvec2, 2> piece{};  // [x, y]: t0 <= x < y <= t1
};
ConeIntervals cone_intervals(const glm::dvec3& apex, const glm::dvec3& axis, double half_angle,
                             const glm::dvec3& origin, const glm::dvec3& dir, double t0, double t1);

// The gobo's right and up axes (docs/design.md §1): right = normalize(axis × gobo_up),
// up = right × axis. If gobo_up is parallel to the axis (the loader prevents it)
// another world axis stands in, so the frame is never NaN.
void gobo_frame(const Light& light, glm::dvec3& right, glm::dvec3& up);

// Gobo texture coordinates of `dir` (unit, from the light): u, v in [0, 1] over
// the square circumscribing the cone (tan of the angles off the axis scaled by
// tan(cone_deg)); v = 1 is the gobo's top row, toward gobo_up. Local frame:
// right = normalize(axis × gobo_up), up = right × axis. Directions at or behind
// the light's plane (and any direction when cone_deg >= 90) map to (-1, -1),
// outside the gobo.
glm::dvec2 gobo_uv(const Light& light, const glm::dvec3& dir);

// Bilinear lookup with clamp-to-edge; (u, v) as gobo_uv returns.
glm::dvec3 sample_gobo(const Image& gobo, const glm::dvec2& uv);

// ---- a directional light's beam (scene.hpp Beam); light.beam must be set ------
// The box: the aperture rectangle of size w × h centred at beam.origin,
// spanned by gobo_frame's right (width) and up (height), perpendicular to the
// light's direction, extended beam.length downstream.

// Whether the light is directional with a beam (a beam on other lights means nothing).
inline bool has_beam(const Light& light) { return light.type == LightType::directional && light.beam; }

// Gobo coordinates of x across the aperture: u = 0.5 + (x − origin)·right / w,
// v = 0.5 + (x − origin)·up / h (v = 1 toward up, as gobo_uv); [0, 1]² inside.
glm::dvec2 beam_uv(const Light& light, const glm::dvec3& x);

// s = (x − origin)·direction: how far downstream of the aperture's plane x lies.
double beam_depth(const Light& light, const glm::dvec3& x);

// Whether x lies in the closed box: beam_uv in [0, 1]² and 0 <= s <= length.
bool inside_beam(const Light& light, const glm::dvec3& x);

// The part of [t0, t1] of the line origin + t·dir (unit) inside the box, by
// slabs in the beam's frame (slab.hpp): empty() when the line misses it. A
// line parallel to a face (exactly or to rounding) gives no NaN.
Interval beam_interval(const Light& light, const glm::dvec3& origin, const glm::dvec3& dir, double t0,
                       double t1);

// The light map (Dobashi 2000 §4: I(θ, φ) stored as a texture): the unitless
// per-channel factor of what the light sends to x that depends on where x is
// across the light — spot: spot_cone · gobo colour toward x; directional with
// a beam: (x inside the beam) · gobo colour at beam_uv(x) (1 without a gobo);
// point light and unbounded directional light: 1.
glm::dvec3 light_map(const Light& light, const glm::dvec3& x);

// I(ω) in W/sr per channel for point and spot lights toward unit `dir` from the
// light (intensity · cone factor · gobo colour); a directional light's irradiance.
glm::dvec3 radiant_intensity(const Light& light, const glm::dvec3& dir);

// The distance below which r is clamped in the 1/r² falloff (metres, the scene
// unit): ∫ dx/r² along a ray through the light diverges, so every integrand uses
// max(r, min_light_distance). 1 µm is far below any scene scale (>= centimetres),
// so the clamp changes nothing unless the light lies within 1 µm of the ray.
inline constexpr double min_light_distance = 1e-6;

// What arrives at `x` from the light, before visibility and extinction on the
// light's leg: I(ω)/r² (physical), I(ω)/(a1 r² + a0) (simplified, Nilsson eq. 2.13),
// or the irradiance of a directional light times its light_map (a beam's
// box and gobo). `to_light` receives the unit direction from x toward the
// light and `distance` the distance (infinity for directional lights).
// Directional lights send their irradiance under both light models (no
// distance falloff); r is clamped at min_light_distance.
struct Arrival {
  glm::dvec3 irradiance{0.0};
  glm::dvec3 to_light{0.0};
  double distance = 0.0;
};
Arrival arrival(const Light& light, const LightModel& model, const glm::dvec3& x);

}  // namespace airlight::optics
