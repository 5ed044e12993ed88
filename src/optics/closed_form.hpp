#pragma once
// Closed forms of the unoccluded airlight of one isotropic point light along a
// ray from the eye (distance 0) to distance d, in a homogeneous medium. Their one
// remaining 1D integral is evaluated by adaptive Gauss–Kronrod to ~1e-12
// relative. Like the quadrature they clamp r at min_light_distance (light.hpp),
// which matters only within 1 µm of the light: through it they are finite.
#include <glm/vec3.hpp>

namespace airlight::optics {

// Sun et al. 2005's F(u, v) = ∫_0^v exp(-u tan ξ) dξ (Kingston eq. 40), u >= 0,
// 0 <= v <= π/2; ~1e-12 relative; F(0, v) = v.
double sun_F(double u, double v);

// Sun et al. 2005 as derived by Kingston (eqs. 36-39): single scattering with
// extinction on both legs, isotropic phase 1/(4π). Evaluated as the single
// integral A0·∫_{γ/2}^{A2} exp(-σt(d_lv cos γ + d_lv sin γ tan ξ)) dξ (never the
// difference of two F values), and as the integral over x itself where
// sin γ < 1e-6 (rays through or along the line to the light).
//   d_lv: distance eye→light, gamma: angle between the view ray and the direction
//   to the light, d_vp: length of the view segment.
double sun_airlight(double sigma_s, double sigma_t, double I0, double d_lv, double gamma, double d_vp);

// The same for a ray (origin, unit dir) and a light position, from 0 to d.
double sun_airlight(double sigma_s, double sigma_t, double I0, const glm::dvec3& origin,
                    const glm::dvec3& dir, const glm::dvec3& light, double d);

// Nilsson's simplified model (eq. 2.17), Ê(z0, z1) for I/(a1 r² + a0), T = 1,
// isotropic phase, times the intensity I. Finite for a1 = 0.
double nilsson_airlight(double sigma_s, double I, double a0, double a1, const glm::dvec3& origin,
                        const glm::dvec3& dir, const glm::dvec3& light, double z0, double z1);

}  // namespace airlight::optics
