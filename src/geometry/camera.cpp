#include "geometry/camera.hpp"

#include <airlight/error.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <limits>

namespace airlight::geometry {
namespace {

// A unit vector perpendicular-enough to `forward` to orient the frame: the
// camera's up unless it is (nearly) parallel to the view direction.
glm::dvec3 frame_up_hint(const glm::dvec3& forward, const glm::dvec3& up) {
  constexpr double parallel = 1.0 - 1e-9;
  for (const glm::dvec3& hint : {up, glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0)}) {
    const double length = glm::length(hint);
    if (length > 0.0 && std::abs(glm::dot(hint / length, forward)) < parallel) return hint / length;
  }
  return glm::dvec3(0, 1, 0);  // unreachable: +z and +x cannot both be parallel to forward
}

// Distance to a plane perpendicular to the view axis at view depth `depth`.
double plane_distance(const Camera& camera, const glm::dvec3& dir, double depth) {
  const double cos_axis = glm::dot(dir, camera_basis(camera).forward);
  return cos_axis > 0.0 ? depth / cos_axis : std::numeric_limits<double>::infinity();
}

}  // namespace

CameraBasis camera_basis(const Camera& camera) {
  CameraBasis frame;
  frame.position = glm::dvec3(camera.position);
  const glm::dvec3 view = glm::dvec3(camera.look_at) - frame.position;
  if (!(glm::length(view) > 0.0)) throw Failure("camera: position and look_at coincide");
  frame.forward = glm::normalize(view);
  frame.right = glm::normalize(glm::cross(frame.forward, frame_up_hint(frame.forward, camera.up)));
  frame.up = glm::cross(frame.right, frame.forward);
  frame.tan_half_fov_y = std::tan(glm::radians(static_cast<double>(camera.fov_y_deg)) * 0.5);
  return frame;
}

optics::Ray primary_ray(const Camera& camera, int width, int height, double px, double py) {
  const CameraBasis frame = camera_basis(camera);
  const double aspect = static_cast<double>(width) / height;
  // Image-plane coordinates at unit distance: x right, y up (py grows downward).
  const double x = (2.0 * px / width - 1.0) * frame.tan_half_fov_y * aspect;
  const double y = (1.0 - 2.0 * py / height) * frame.tan_half_fov_y;
  return {frame.position, glm::normalize(frame.forward + x * frame.right + y * frame.up)};
}

double far_distance(const Camera& camera, const glm::dvec3& dir) {
  return plane_distance(camera, dir, camera.far);
}

double near_distance(const Camera& camera, const glm::dvec3& dir) {
  return plane_distance(camera, dir, camera.near);
}

double corner_distance(const Camera& camera, double aspect, double depth) {
  const double tan_y = std::tan(0.5 * glm::radians(double(camera.fov_y_deg)));
  return depth * std::sqrt(1.0 + tan_y * tan_y * (1.0 + aspect * aspect));
}

double view_depth(const Camera& camera, const glm::dvec3& dir, double t) {
  return t * glm::dot(dir, camera_basis(camera).forward);
}

}  // namespace airlight::geometry
