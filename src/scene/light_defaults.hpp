#pragma once
// Conventions for lights shared by the scene parser and the built-in scenes.
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace airlight::scene_light {

// Below this |a × b| two directions count as parallel (about 0.06°).
inline constexpr double kParallel = 1e-3;

// In double, so that neither tiny nor huge float vectors lose their direction.
inline bool parallel(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::length(glm::cross(glm::normalize(a), glm::normalize(b))) < kParallel;
}

// The gobo's up (docs/design.md §1): world up, or +z for a spot pointing (nearly)
// straight up or down, where world up cannot orient it.
inline glm::vec3 default_gobo_up(const glm::vec3& axis) {
  const glm::vec3 up(0, 1, 0);
  return parallel(axis, up) ? glm::vec3(0, 0, 1) : up;
}

}  // namespace airlight::scene_light
