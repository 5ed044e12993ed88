#pragma once
// The pinhole camera of docs/design.md §5: from `position` toward `look_at`, fov_y_deg the
// full vertical field of view, aspect W/H, pixel (i, j) with j = 0 the top row
// sampled through its centre (px, py) = (i + 0.5, j + 0.5). Right-handed, as
// glm::lookAt: the camera looks along -z of its own frame, x right, y up.
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>
#include <optics/airlight.hpp>

namespace airlight::geometry {

// The camera's orthonormal frame in world space.
struct CameraBasis {
  glm::dvec3 position{0.0};
  glm::dvec3 forward{0, 0, -1}, right{1, 0, 0}, up{0, 1, 0};
  double tan_half_fov_y = 1.0;
};

// Throws airlight::Failure when position == look_at. When `up` is parallel to
// the view direction, world +z (or +x if that is parallel too) orients the frame.
CameraBasis camera_basis(const Camera& camera);

// The ray through image position (px, py) in pixels of a width × height image,
// (0, 0) the top-left corner of the image: origin at the eye, unit direction.
optics::Ray primary_ray(const Camera& camera, int width, int height, double px, double py);

// Distance along unit `dir` (from the eye) to the far and near planes: the planes
// a GPU depth buffer clips at, so far / dot(dir, forward). Infinity for
// directions that never meet the plane (dot <= 0).
double far_distance(const Camera& camera, const glm::dvec3& dir);
double near_distance(const Camera& camera, const glm::dvec3& dir);

// How far from the eye a point at view depth `depth` may lie in a frame of
// aspect W/H: along the image's corner rays, depth·√(1 + tan²(fov_y/2)·(1 + aspect²)).
double corner_distance(const Camera& camera, double aspect, double depth);

// View depth of the point at distance t along unit `dir`: t · dot(dir, forward).
double view_depth(const Camera& camera, const glm::dvec3& dir, double t);

}  // namespace airlight::geometry
