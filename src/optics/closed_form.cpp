#include "optics/closed_form.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

#include "optics/falloff.hpp"
#include "optics/gauss_kronrod.hpp"
#include "optics/light.hpp"

namespace airlight::optics {
namespace {

constexpr double pi = std::numbers::pi;
constexpr double eps = min_light_distance;  // the 1/r² clamp shared with the quadrature

// Accuracy of the 1D integrals below: far beyond the float tables they replace.
gk::Settings closed_form_settings() {
  gk::Settings s;
  s.rel_tol = 1e-12;
  s.max_depth = 60;
  return s;
}

// ∫_lo^hi exp(-(offset + u·tan ξ)) dξ with the exponent summed before exp, so that
// a large offset of either sign never overflows when the sum stays >= 0.
double angular_integral(double u, double offset, double lo, double hi) {
  if (!(hi > lo)) return 0.0;
  if (u == 0.0) return std::exp(-offset) * (hi - lo);
  auto f = [&](double xi) { return std::exp(-(offset + u * std::tan(xi))); };
  return gk::integrate<double>(f, {lo, hi}, closed_form_settings());
}

// The geometry of the view segment x in [0, d] relative to the light: the foot
// of the perpendicular at x = xs, at distance r0 >= 0 from the light.
struct Segment {
  double xs, r0, d;
};

// Kingston eqs. 36-39 with the substitution x - xs = r0·tan(2ξ - π/2): dx/r² =
// 2dξ/r0 and x + r = xs + r0·tan ξ. The ξ range starts at γ/2 (x = 0) and spans
// half the angle the segment subtends at the light, from atan2 of the cross and
// dot products of the two light→end vectors (no cancellation, unlike
// A2 - γ/2 from eq. 39, and valid at σt = 0).
double sun_angular(double sigma_s, double sigma_t, double I0, const Segment& s) {
  const double xi0 = 0.5 * std::atan2(s.r0, s.xs);
  const double half_angle = 0.5 * std::atan2(s.r0 * s.d, s.r0 * s.r0 + s.xs * (s.xs - s.d));
  const double A0 = sigma_s * I0 / (2.0 * pi * s.r0);  // Kingston's A0, its e^{-σt d_lv cos γ} moved inside
  return A0 * angular_integral(sigma_t * s.r0, sigma_t * s.xs, xi0, xi0 + half_angle);
}

// The defining integral in x (docs/design.md §1) for rays through or nearly along the
// line to the light, where the angular form's 1/r0 is singular; r is clamped at
// ε like the quadrature, so a light on the segment gives a finite, large value.
double sun_direct(double sigma_s, double sigma_t, double I0, const Segment& s) {
  auto f = [&](double x) {
    const double r = std::hypot(s.r0, x - s.xs);
    const double r_clamped = std::max(r, eps);
    return std::exp(-sigma_t * (x + r)) / (r_clamped * r_clamped);
  };
  std::vector<double> breaks{0.0, s.d};
  for (double t : falloff_breaks(s.xs, s.r0, s.d))
    if (t > 0.0 && t < s.d) breaks.push_back(t);
  std::sort(breaks.begin(), breaks.end());
  return sigma_s * I0 / (4.0 * pi) * gk::integrate<double>(f, breaks, closed_form_settings());
}

double sun_segment(double sigma_s, double sigma_t, double I0, const Segment& s) {
  if (!(s.d > 0.0)) return 0.0;
  const double d_lv = std::hypot(s.xs, s.r0);
  // sin γ < 1e-6: the ξ range and 1/r0 lose digits; r0 < ε: the clamp is active.
  if (s.r0 < eps || s.r0 < 1e-6 * d_lv) return sun_direct(sigma_s, sigma_t, I0, s);
  return sun_angular(sigma_s, sigma_t, I0, s);
}

Segment segment_of(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& light,
                   double d) {
  const glm::dvec3 delta = light - origin;
  const double xs = glm::dot(delta, dir);
  return {xs, glm::length(delta - xs * dir), d};  // Nilsson eq. 2.16, r0 = |Δ - zs·Ω| (README)
}

// ∫_{s0}^{s1} ds / (a1 s² + B), B >= 0 (Nilsson eq. 2.17 before σs/(4π)):
// (atan(q s1) - atan(q s0)) / (q B), q = sqrt(a1/B), the difference of atans
// taken as one atan2. Its limits, exact to ~(q s)^±2 < 1e-200: (s1 - s0)/B as
// a1 -> 0, and (1/s0 - 1/s1)/a1 as B -> 0 (then 0 must lie outside [s0, s1]).
double inverse_quadratic_integral(double a1, double B, double s0, double s1) {
  if (!(s1 > s0)) return 0.0;
  const double q = std::sqrt(a1 / B);
  const double s_min = (s0 > 0.0 || s1 < 0.0) ? std::min(std::abs(s0), std::abs(s1)) : 0.0;
  const double s_max = std::max(std::abs(s0), std::abs(s1));
  if (q * s_max < 1e-100) return (s1 - s0) / B;
  if (q * s_min > 1e100) return (s1 - s0) / (a1 * s0 * s1);
  return std::atan2(q * (s1 - s0), 1.0 + q * q * s0 * s1) / (q * B);
}

}  // namespace

double sun_F(double u, double v) { return angular_integral(u, 0.0, 0.0, v); }  // Kingston eq. 40

double sun_airlight(double sigma_s, double sigma_t, double I0, double d_lv, double gamma,
                    double d_vp) {
  return sun_segment(sigma_s, sigma_t, I0,
                     {d_lv * std::cos(gamma), d_lv * std::abs(std::sin(gamma)), d_vp});
}

double sun_airlight(double sigma_s, double sigma_t, double I0, const glm::dvec3& origin,
                    const glm::dvec3& dir, const glm::dvec3& light, double d) {
  return sun_segment(sigma_s, sigma_t, I0, segment_of(origin, dir, light, d));
}

double nilsson_airlight(double sigma_s, double I, double a0, double a1, const glm::dvec3& origin,
                        const glm::dvec3& dir, const glm::dvec3& light, double z0, double z1) {
  if (!(z1 > z0)) return 0.0;
  const Segment g = segment_of(origin, dir, light, 0.0);
  const double s0 = z0 - g.xs, s1 = z1 - g.xs;  // s = z - zs
  double sum = 0.0;
  if (g.r0 >= eps) {
    sum = inverse_quadratic_integral(a1, a1 * g.r0 * g.r0 + a0, s0, s1);
  } else {
    // Within |s| < h the clamped r = ε makes the integrand constant (as in the quadrature).
    const double h = std::sqrt(eps * eps - g.r0 * g.r0);
    const double B = a1 * g.r0 * g.r0 + a0;
    const double in0 = std::clamp(-h, s0, s1), in1 = std::clamp(h, s0, s1);
    sum = inverse_quadratic_integral(a1, B, s0, in0) + (in1 - in0) / (a1 * eps * eps + a0) +
          inverse_quadratic_integral(a1, B, in1, s1);
  }
  return sigma_s * I / (4.0 * pi) * sum;  // Nilsson eq. 2.17 times I
}

}  // namespace airlight::optics
