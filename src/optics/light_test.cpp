#include "optics/light.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <memory>
#include <numbers>

namespace airlight::optics {
namespace {

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

Light spot(float cone_deg, float edge_deg) {
  Light l;
  l.type = LightType::spot;
  l.position = {0, 5, 0};
  l.direction = {0, -1, 0};
  l.intensity = glm::vec3(100.0f);
  l.cone_deg = cone_deg;
  l.edge_deg = edge_deg;
  l.gobo_up = {0, 0, 1};
  return l;
}

// A unit direction at `deg` from the axis -y, tilted toward +x.
glm::dvec3 off_axis(double deg) { return {std::sin(rad(deg)), -std::cos(rad(deg)), 0.0}; }

TEST(Spot, HardCone) {
  const Light l = spot(30.0f, 0.0f);  // Nilsson eq. 2.9: <= cone lit
  EXPECT_EQ(spot_cone(l, off_axis(0.0)), 1.0);
  EXPECT_EQ(spot_cone(l, off_axis(29.999)), 1.0);
  EXPECT_EQ(spot_cone(l, off_axis(30.001)), 0.0);
  EXPECT_EQ(spot_cone(l, off_axis(120.0)), 0.0);
}

TEST(Spot, SmoothEdge) {
  // smoothstep(t) = t²(3 - 2t), t = (cone - angle)/edge; 1e-9: angle round trip.
  const Light l = spot(30.0f, 10.0f);
  EXPECT_EQ(spot_cone(l, off_axis(19.9)), 1.0);
  EXPECT_NEAR(spot_cone(l, off_axis(22.5)), 0.84375, 1e-9);  // t = 0.75
  EXPECT_NEAR(spot_cone(l, off_axis(25.0)), 0.5, 1e-9);      // t = 0.5
  EXPECT_NEAR(spot_cone(l, off_axis(27.5)), 0.15625, 1e-9);  // t = 0.25
  EXPECT_EQ(spot_cone(l, off_axis(30.1)), 0.0);
}

TEST(Gobo, AxisAndConeBoundary) {
  // Frame: axis -y, up (0,0,1) → right = axis × up = (-1, 0, 0), up' = right × axis = (0, 0, 1).
  const Light l = spot(30.0f, 0.0f);
  const glm::dvec2 centre = gobo_uv(l, {0, -1, 0});
  EXPECT_NEAR(centre.x, 0.5, 1e-15);
  EXPECT_NEAR(centre.y, 0.5, 1e-15);
  const double c = rad(30.0);
  const glm::dvec3 axis(0, -1, 0), right(-1, 0, 0), up(0, 0, 1);
  const glm::dvec2 r = gobo_uv(l, std::cos(c) * axis + std::sin(c) * right);
  EXPECT_NEAR(r.x, 1.0, 1e-7);  // 1e-7: cone_deg is a float
  EXPECT_NEAR(r.y, 0.5, 1e-15);
  const glm::dvec2 u = gobo_uv(l, std::cos(c) * axis + std::sin(c) * up);
  EXPECT_NEAR(u.x, 0.5, 1e-15);
  EXPECT_NEAR(u.y, 1.0, 1e-7);
  const glm::dvec2 behind = gobo_uv(l, {0, 1, 0});
  EXPECT_TRUE(behind.x < 0.0 || behind.x > 1.0);
}

Image two_by_two() {
  Image img(2, 2);
  img.at(0, 0) = {1, 0, 0};  // top left
  img.at(1, 0) = {0, 1, 0};  // top right
  img.at(0, 1) = {0, 0, 1};  // bottom left
  img.at(1, 1) = {1, 1, 1};  // bottom right
  return img;
}

TEST(Gobo, BilinearWithPixelCentresAndClampToEdge) {
  const Image img = two_by_two();
  auto expect = [](glm::dvec3 a, glm::dvec3 b) {
    EXPECT_NEAR(glm::length(a - b), 0.0, 1e-12);  // exact up to rounding
  };
  expect(sample_gobo(img, {0.25, 0.75}), {1, 0, 0});  // top-left pixel centre (v = 1 is the top)
  expect(sample_gobo(img, {0.75, 0.25}), {1, 1, 1});
  expect(sample_gobo(img, {0.5, 0.5}), {0.5, 0.5, 0.5});
  expect(sample_gobo(img, {0.0, 1.0}), {1, 0, 0});    // clamp to edge
  expect(sample_gobo(img, {0.5, 1.0}), {0.5, 0.5, 0.0});
}

TEST(Light, RadiantIntensityAppliesConeAndGobo) {
  Light l = spot(30.0f, 0.0f);
  l.gobo = std::make_shared<Image>(two_by_two());
  // Toward gobo_up (+z) and right (-x): the top-right texel (green) region.
  const double a = rad(20.0);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(-std::tan(a), -1.0, std::tan(a)));
  const glm::dvec3 I = radiant_intensity(l, dir);
  EXPECT_NEAR(I.x, 0.0, 1e-9);
  EXPECT_NEAR(I.y, 100.0, 1e-9);
  EXPECT_NEAR(I.z, 0.0, 1e-9);
  EXPECT_EQ(radiant_intensity(l, off_axis(40.0)), glm::dvec3(0.0));  // outside the cone
}

TEST(Light, ArrivalModels) {
  Light l;
  l.position = {0, 3, 4};
  l.intensity = glm::vec3(50.0f);
  const Arrival phys = arrival(l, LightModel{}, {0, 0, 0});
  EXPECT_NEAR(phys.irradiance.x, 50.0 / 25.0, 1e-12);  // I/r²
  EXPECT_NEAR(phys.distance, 5.0, 1e-12);
  EXPECT_NEAR(phys.to_light.z, 0.8, 1e-12);
  const LightModel simple{LightModelType::simplified, 2.0f, 0.5f};
  EXPECT_NEAR(arrival(l, simple, {0, 0, 0}).irradiance.x, 50.0 / (0.5 * 25 + 2), 1e-12);  // eq. 2.13

  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = glm::vec3(2.0f);
  const Arrival s = arrival(sun, LightModel{}, {1, 2, 3});
  EXPECT_EQ(s.irradiance, glm::dvec3(2.0));
  EXPECT_TRUE(std::isinf(s.distance));
  EXPECT_EQ(s.to_light, glm::dvec3(0, 1, 0));

  // At the light itself r is clamped at min_light_distance: finite, no NaN.
  const Arrival at = arrival(l, LightModel{}, glm::dvec3(l.position));
  EXPECT_NEAR(at.irradiance.x, 50.0 / (min_light_distance * min_light_distance), 1e-3);
  EXPECT_TRUE(std::isfinite(glm::length(at.to_light)));
}

}  // namespace
}  // namespace airlight::optics
