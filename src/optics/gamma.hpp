#pragma once
// Γ(t0 → t1): the unoccluded airlight of one light along a view segment in the
// homogeneous medium that fills space (docs/design.md §1 with V = 1), in closed form.
// Bounded volumes are ignored (the closed forms hold in one homogeneous medium
// only); a gobo is ignored too (Γ uses the cone or the beam box, not the light
// map's colours). GLSL twin: shaders/optics/gamma.glsl, src/methods/kit/gamma/closed_form.glsl.
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "optics/airlight.hpp"

namespace airlight::optics {

// Γ per channel over [t0, t1] of the ray: simplified light model → Nilsson
// eq. 2.17; isotropic phase → Sun et al. 2005 (Kingston eqs. 36-40); other
// phases (and smooth-edged spots) → Biri 2006's angular formulation with
// Gauss–Legendre nodes in the angle; spot lights over their cone_intervals,
// cut again where a smooth edge begins (its smoothstep is integrated with the
// phase; the simplified model keeps Nilsson's hard cut, eq. 2.9, and ignores
// the edge); directional lights by the exact exponential form, over
// beam_interval for a beam. Within 1 µm of the line through a point or spot
// light, the angular and Sun-table paths move the light 1 µm off the line
// (finite; the quadrature clamps r instead). 0 when t1 <= t0.
glm::dvec3 gamma(const Medium& medium, const LightModel& model, const Light& light, const Ray& ray,
                 double t0, double t1);

// Sun et al.'s F(u, v) (Kingston eq. 40) tabulated for the `analytic` method's
// SUN_F_TABLE variant. Texel (i, j) is texels[j * width + i]: upload as an R32F
// texture of width × height with row j at GL's t = j (nearest filtering; the
// shader filters bilinearly with texelFetch, as lookup() does here in float).
//
// Parametrization: the table holds R = F / B with B(u, v) = v·(1 - e^{-uv})/(uv)
// (sun_asymptote: F's limits v as u → 0, (1 - e^{-uv})/u as v → 0, 1/u as
// u → ∞), which stays in (0.5, 1], on a uniform grid in ln u (columns) and
// ln tan v (rows): in those variables F's features all have width O(1).
// Texel (i, j) sits at ln u = log_u_min + i·log_u_step, ln tan v =
// log_tan_min + j·log_tan_step; outside the grid coordinates clamp (R tends to
// 1 at both ends in u and as v → 0, and to its v = π/2 value within 1e-4).
// Measured relative error of F: gamma_test.cpp (SunTable.RelativeErrorBound).
inline constexpr int sun_table_width = 256, sun_table_height = 256;
inline constexpr float sun_table_log_u_min = -12.0f, sun_table_log_u_step = 18.0f / 255.0f;
inline constexpr float sun_table_log_tan_min = -6.0f, sun_table_log_tan_step = 15.0f / 255.0f;

struct SunTable {
  int width = 0, height = 0;
  std::vector<float> texels;

  // F(u, v) for u >= 0 (u = +∞ allowed), v in [0, π/2], exactly as the GLSL
  // twin computes it (float arithmetic, same order of operations).
  float F(float u, float v) const;
  // The same given tan v as well (the Γ path knows tan ξ without an angle).
  float F_tan(float u, float tan_v, float v) const;
};

// B(u, v) above, in float as the GLSL.
float sun_asymptote(float u, float v);

// The table at sun_table_width × sun_table_height (its measured error:
// docs/decisions.md, SunTable).
SunTable build_sun_table();

// Sun et al.'s Γ along [0, d] of the ray (origin, unit dir) for a point light,
// isotropic phase, with F from the table (Kingston eq. 38, A0·e^{-σt xs}·
// [F(u, ξ1) - F(u, ξ0)], u = σt·r0) wherever that difference is
// well-conditioned: F1 + F0 <= sun_table_max_condition·(F1 - F0), which bounds
// the table's error amplification; elsewhere (large optical depth, short
// segments) the integral itself (sun_airlight). In float, as the GLSL.
inline constexpr float sun_table_max_condition = 8.0f;
inline constexpr float sun_table_max_gain = 30.0f;  // e^{-σt xs} <= e^30 (light behind the eye)
double sun_airlight_table(const SunTable& table, double sigma_s, double sigma_t, double I0, const glm::dvec3& origin,
                          const glm::dvec3& dir, const glm::dvec3& light, double d);

}  // namespace airlight::optics
