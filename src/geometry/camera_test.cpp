#include "geometry/camera.hpp"

#include <airlight/error.hpp>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <numbers>

namespace airlight::geometry {
namespace {

// Exact in binary floating point up to rounding of tan and normalize.
constexpr double tight = 1e-12;

Camera looking_down_minus_z() {
  Camera camera;
  camera.position = {0, 0, 0};
  camera.look_at = {0, 0, -1};
  camera.up = {0, 1, 0};
  camera.fov_y_deg = 90.0f;
  camera.near = 0.5f;
  camera.far = 10.0f;
  return camera;
}

TEST(Camera, CentreOfOddImageLooksAlongTheAxis) {
  const optics::Ray ray = primary_ray(looking_down_minus_z(), 5, 3, 2.5, 1.5);
  EXPECT_NEAR(ray.dir.x, 0.0, tight);
  EXPECT_NEAR(ray.dir.y, 0.0, tight);
  EXPECT_NEAR(ray.dir.z, -1.0, tight);
}

TEST(Camera, ImageCornersSpanTheVerticalFovAndAspect) {
  // fov_y = 90°: the top edge is at y = z, the right edge at x = aspect · z.
  const Camera camera = looking_down_minus_z();
  const optics::Ray top_left = primary_ray(camera, 8, 4, 0.0, 0.0);
  EXPECT_NEAR(top_left.dir.y / -top_left.dir.z, 1.0, tight);
  EXPECT_NEAR(top_left.dir.x / -top_left.dir.z, -2.0, tight);
  const optics::Ray bottom_right = primary_ray(camera, 8, 4, 8.0, 4.0);
  EXPECT_NEAR(bottom_right.dir.y / -bottom_right.dir.z, -1.0, tight);
  EXPECT_NEAR(bottom_right.dir.x / -bottom_right.dir.z, 2.0, tight);
}

TEST(Camera, RowZeroIsTheTopAndDirectionsAreUnit) {
  const Camera camera = looking_down_minus_z();
  const optics::Ray top = primary_ray(camera, 4, 4, 2.0, 0.5);
  const optics::Ray bottom = primary_ray(camera, 4, 4, 2.0, 3.5);
  EXPECT_GT(top.dir.y, 0.0);
  EXPECT_LT(bottom.dir.y, 0.0);
  EXPECT_NEAR(glm::length(top.dir), 1.0, tight);
}

TEST(Camera, FarAndNearArePlanesNotSpheres) {
  const Camera camera = looking_down_minus_z();
  EXPECT_NEAR(far_distance(camera, {0, 0, -1}), 10.0, tight);
  const glm::dvec3 diagonal = glm::normalize(glm::dvec3(1, 0, -1));
  EXPECT_NEAR(far_distance(camera, diagonal), 10.0 * std::numbers::sqrt2, 1e-9);
  EXPECT_NEAR(near_distance(camera, diagonal), 0.5 * std::numbers::sqrt2, 1e-9);
  EXPECT_NEAR(view_depth(camera, diagonal, far_distance(camera, diagonal)), 10.0, 1e-9);
  EXPECT_TRUE(std::isinf(far_distance(camera, {0, 0, 1})));
}

TEST(Camera, FrameFollowsLookAtLikeGlmLookAt) {
  Camera camera;
  camera.position = {0, 2, 8};
  camera.look_at = {0, 2, 0};
  const CameraBasis frame = camera_basis(camera);
  EXPECT_NEAR(frame.forward.z, -1.0, tight);
  EXPECT_NEAR(frame.right.x, 1.0, tight);
  EXPECT_NEAR(frame.up.y, 1.0, tight);
}

TEST(Camera, UpParallelToViewStillGivesAnOrthonormalFrame) {
  Camera camera;
  camera.position = {0, 5, 0};
  camera.look_at = {0, 0, 0};
  camera.up = {0, 1, 0};
  const CameraBasis frame = camera_basis(camera);
  EXPECT_NEAR(glm::dot(frame.forward, frame.right), 0.0, tight);
  EXPECT_NEAR(glm::dot(frame.forward, frame.up), 0.0, tight);
  EXPECT_NEAR(glm::length(frame.right), 1.0, tight);
  const optics::Ray ray = primary_ray(camera, 3, 3, 1.5, 1.5);
  EXPECT_NEAR(ray.dir.y, -1.0, tight);
}

TEST(Camera, CoincidentPositionAndLookAtIsAFailure) {
  Camera camera;
  camera.look_at = camera.position;
  EXPECT_THROW(camera_basis(camera), Failure);
}

}  // namespace
}  // namespace airlight::geometry
