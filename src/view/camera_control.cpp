#include "view/camera_control.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace airlight::view {
namespace {

constexpr float max_elevation = glm::radians(89.0f);

// `v` (from a centre) turned by yaw about `up` and pitched toward it, its
// elevation clamped; its length is kept.
glm::vec3 turn(const glm::vec3& v, const glm::vec3& up_in, float yaw_deg, float pitch_deg) {
  const glm::vec3 up = glm::normalize(up_in);
  const float length = glm::length(v);
  const glm::vec3 d = v / length;
  glm::vec3 flat = d - glm::dot(d, up) * up;  // the horizontal part
  if (glm::length(flat) < 1e-6f) flat = glm::abs(up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
  flat = glm::normalize(flat - glm::dot(flat, up) * up);
  const glm::vec3 side = glm::cross(up, flat);
  const float azimuth = std::atan2(glm::dot(d, side), glm::dot(d, flat)) + glm::radians(yaw_deg);
  const float elevation = std::clamp(std::asin(std::clamp(glm::dot(d, up), -1.0f, 1.0f)) + glm::radians(pitch_deg),
                                     -max_elevation, max_elevation);
  const glm::vec3 horizontal = std::cos(azimuth) * flat + std::sin(azimuth) * side;
  return length * (std::cos(elevation) * horizontal + std::sin(elevation) * up);
}

}  // namespace

Camera orbit(const Camera& camera, float yaw_deg, float pitch_deg) {
  Camera c = camera;
  // The eye's offset from the centre turns opposite to the view: dragging right
  // swings the eye left around the target, as orbit controls do.
  c.position = c.look_at + turn(c.position - c.look_at, c.up, -yaw_deg, -pitch_deg);
  return c;
}

Camera look(const Camera& camera, float yaw_deg, float pitch_deg) {
  Camera c = camera;
  c.look_at = c.position + turn(c.look_at - c.position, c.up, yaw_deg, pitch_deg);
  return c;
}

Camera fly(const Camera& camera, const glm::vec3& move) {
  Camera c = camera;
  const glm::vec3 forward = glm::normalize(c.look_at - c.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, c.up));
  const glm::vec3 up = glm::cross(right, forward);
  const glm::vec3 step = move.x * right + move.y * up + move.z * forward;
  c.position += step;
  c.look_at += step;
  return c;
}

Camera dolly(const Camera& camera, float factor) {
  Camera c = camera;
  const glm::vec3 offset = c.position - c.look_at;
  const float distance = std::max(glm::length(offset) * factor, 1e-3f);
  c.position = c.look_at + glm::normalize(offset) * distance;
  return c;
}

}  // namespace airlight::view
