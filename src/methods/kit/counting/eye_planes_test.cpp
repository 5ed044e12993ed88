// take_planes_at_eye (lit_interval_pass.hpp): which counted triangles pass
// through the eye, what becomes of them, and where the caller counts instead.
#include "methods/kit/counting/lit_interval_pass.hpp"

#include <gtest/gtest.h>

namespace airlight::kit {
namespace {

// The shadow plane of the edge (0, 0, 0)–(1, 0, 0) of a point light at
// (0.5, 1, 0), the plane z = 0, as the two triangles shadow_planes draws (the
// edge, and its ends pushed to infinity away from the light), weight 1.
Light point() {
  Light light;
  light.type = LightType::point;
  light.position = {0.5f, 1.0f, 0.0f};
  return light;
}

std::vector<CountedTriangle> wedge(int weight = 1) {
  const glm::dvec4 a(0, 0, 0, 1), b(1, 0, 0, 1), light(0.5, 1, 0, 1);
  const glm::vec4 a_far(glm::vec3(a - light), 0.0f), b_far(glm::vec3(b - light), 0.0f);
  const glm::vec4 plane = counted_plane(a, b, light);
  return {{{glm::vec4(a), glm::vec4(b), b_far}, plane, {0, weight, 0, 0}},
          {{glm::vec4(a), b_far, a_far}, plane, {0, weight, 0, 0}}};
}

TEST(EyePlanes, AnEyeOnAShadowPlaneTakesItsTriangleOut) {
  std::vector<CountedTriangle> triangles = wedge();
  const glm::dvec3 eye(0.5, -2.0, 1e-9);  // below the edge, in the plane z = 0 but for rounding
  glm::dvec3 beside(0.0);
  const std::vector<EyePlane> planes = take_planes_at_eye(triangles, 0, 0, point(), eye, max_eye_planes, beside);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_EQ(planes[0].light, 0);
  EXPECT_EQ(planes[0].weight, 1);
  EXPECT_NEAR(std::abs(planes[0].normal.z), 1.0, 1e-6);
  // Both triangles count nothing now: the one the eye is in and the other, edge-on from it.
  EXPECT_EQ(triangles[0].light_weight.y, 0);
  EXPECT_EQ(triangles[1].light_weight.y, 0);
  // beside: off the plane on its negative side by more than the tolerance (1e-5 of the magnitude, 2.06 here).
  EXPECT_LT(glm::dot(glm::dvec3(planes[0].normal), beside - eye), -1e-5 * 2.0);
  EXPECT_LT(glm::distance(beside, eye), 1e-4);
}

// Off the plane by 50 times the tolerance, the wedge stays drawn. On the plane
// but beside the wedge (above the edge, on the light's side), a ray from the
// eye crosses neither triangle, and edge-on the rasterizer could only get them
// wrong: they are taken out, without a plane.
TEST(EyePlanes, AnEyeOffThePlaneOrBesideTheWedgeGivesNoPlane) {
  const struct {
    glm::dvec3 eye;
    int weight_after;
  } cases[] = {{{0.5, -2.0, 1e-3}, 1}, {{3.0, 0.5, 0.0}, 0}};
  for (const auto& c : cases) {
    std::vector<CountedTriangle> triangles = wedge();
    glm::dvec3 beside = c.eye;
    EXPECT_TRUE(take_planes_at_eye(triangles, 0, 0, point(), c.eye, max_eye_planes, beside).empty());
    EXPECT_EQ(beside, c.eye);
    EXPECT_EQ(triangles[0].light_weight.y, c.weight_after);
    EXPECT_EQ(triangles[1].light_weight.y, c.weight_after);
  }
}

TEST(EyePlanes, OtherLightsAndEarlierTrianglesAreLeftAlone) {
  std::vector<CountedTriangle> triangles = wedge();
  const glm::dvec3 eye(0.5, -2.0, 0.0);
  glm::dvec3 beside(0.0);
  EXPECT_TRUE(take_planes_at_eye(triangles, 0, 1, point(), eye, max_eye_planes, beside).empty());  // light 1 has none
  EXPECT_TRUE(take_planes_at_eye(triangles, 2, 0, point(), eye, max_eye_planes, beside).empty());  // none from index 2
  EXPECT_TRUE(take_planes_at_eye(triangles, 0, 0, point(), eye, 0, beside).empty());               // no room
  EXPECT_EQ(triangles[0].light_weight.y, 1);
}

}  // namespace
}  // namespace airlight::kit
