#pragma once
// Scenes and measures shared by the optics tests.
#include <airlight/scene.hpp>
#include <algorithm>
#include <cmath>
#include <glm/vec3.hpp>

namespace airlight::optics::testing {

// A homogeneous isotropic medium filling space and nothing else.
inline Scene homogeneous_scene(float sigma_s, float sigma_a) {
  Scene s;
  s.medium.sigma_s = glm::vec3(sigma_s);
  s.medium.sigma_a = glm::vec3(sigma_a);
  return s;
}

inline Light point_light(const glm::vec3& position, float intensity) {
  Light l;
  l.type = LightType::point;
  l.position = position;
  l.intensity = glm::vec3(intensity);
  return l;
}

// |a - b| / |b|, and 0 when both are 0 (a zero reference needs a zero answer).
inline double relative_error(double a, double b) {
  if (a == b) return 0.0;
  return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

}  // namespace airlight::optics::testing
