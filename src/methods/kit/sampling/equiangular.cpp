#include "methods/kit/sampling/equiangular.hpp"

#include "optics/light.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace airlight::kit {

Segment uniform_segment(double a, double b) { return {a, b, 0.0, 0.0, 0.0, 0.0}; }

Segment equiangular_segment(double a, double b, const glm::dvec3& eye, const glm::dvec3& dir,
                            const glm::dvec3& light) {
  const glm::dvec3 delta = light - eye;
  const double foot = glm::dot(delta, dir);
  // |Δ − foot·dir|, not sqrt(|Δ|² − foot²), which cancels for a light near the ray (Nilsson eq. 2.16).
  const double h = std::max(glm::length(delta - foot * dir), std::max(1e-4 * (b - a), optics::min_light_distance));
  return {a, b, foot, h, std::atan2(a - foot, h), std::atan2(b - foot, h)};
}

glm::dvec2 segment_sample(const Segment& s, double u, int n) {
  if (s.h == 0.0) return {s.a + u * (s.b - s.a), (s.b - s.a) / n};
  const double y = s.h * std::tan(s.theta_a + u * (s.theta_b - s.theta_a));
  return {s.foot + y, (s.theta_b - s.theta_a) / n * (s.h + y * y / s.h)};  // h/cos²θ = h + y²/h
}

}  // namespace airlight::kit
