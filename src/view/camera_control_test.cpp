#include "view/camera_control.hpp"

#include <glm/geometric.hpp>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

namespace airlight::view {
namespace {

// Float trigonometry on metre-sized vectors: 1e-5 m.
constexpr float tolerance = 1e-5f;

Camera scene_camera() {
  Camera c;
  c.position = {0.0f, 2.4f, 8.0f};
  c.look_at = {0.3f, 1.4f, 0.0f};
  return c;
}

float elevation_deg(const glm::vec3& v) { return glm::degrees(std::asin(glm::normalize(v).y)); }

TEST(CameraControl, OrbitKeepsTheTargetAndDistance) {
  const Camera c = scene_camera();
  const Camera o = orbit(c, 30.0f, 10.0f);
  EXPECT_EQ(o.look_at, c.look_at);
  EXPECT_NEAR(glm::distance(o.position, o.look_at), glm::distance(c.position, c.look_at), tolerance);
  EXPECT_NEAR(elevation_deg(o.position - o.look_at), elevation_deg(c.position - c.look_at) - 10.0f, 1e-3f);
}

TEST(CameraControl, OrbitThereAndBackReturns) {
  const Camera c = scene_camera();
  const Camera back = orbit(orbit(c, 40.0f, 0.0f), -40.0f, 0.0f);
  EXPECT_LT(glm::distance(back.position, c.position), tolerance);
}

TEST(CameraControl, ElevationStopsShortOfUp) {
  const Camera o = orbit(scene_camera(), 0.0f, -500.0f);
  EXPECT_NEAR(elevation_deg(o.position - o.look_at), 89.0f, 1e-3f);
  const Camera l = look(scene_camera(), 0.0f, 500.0f);
  EXPECT_NEAR(elevation_deg(l.look_at - l.position), 89.0f, 1e-3f);
}

TEST(CameraControl, LookTurnsAboutTheEye) {
  const Camera c = scene_camera();
  const Camera l = look(c, 90.0f, 0.0f);
  EXPECT_EQ(l.position, c.position);
  const glm::vec3 before = c.look_at - c.position, after = l.look_at - l.position;
  EXPECT_NEAR(glm::length(after), glm::length(before), tolerance);
  // A quarter turn about +y: the horizontal parts are perpendicular.
  EXPECT_NEAR(glm::dot(glm::vec2(before.x, before.z), glm::vec2(after.x, after.z)), 0.0f, 1e-4f);
}

TEST(CameraControl, FlyMovesEyeAndTargetTogether) {
  const Camera c = scene_camera();
  const Camera f = fly(c, {0.0f, 0.0f, 1.0f});
  const glm::vec3 forward = glm::normalize(c.look_at - c.position);
  EXPECT_LT(glm::distance(f.position, c.position + forward), tolerance);
  EXPECT_LT(glm::distance(f.look_at - f.position, c.look_at - c.position), tolerance);
  const Camera r = fly(c, {1.0f, 0.0f, 0.0f});
  EXPECT_NEAR(glm::dot(r.position - c.position, forward), 0.0f, tolerance);
  EXPECT_GT((r.position - c.position).x, 0.9f);  // right of a camera looking down −z is +x
}

TEST(CameraControl, DollyApproachesButNeverReachesTheTarget) {
  const Camera c = scene_camera();
  EXPECT_NEAR(glm::distance(dolly(c, 0.5f).position, c.look_at), 0.5f * glm::distance(c.position, c.look_at),
              tolerance);
  EXPECT_GT(glm::distance(dolly(c, 0.0f).position, c.look_at), 0.0f);
}

}  // namespace
}  // namespace airlight::view
