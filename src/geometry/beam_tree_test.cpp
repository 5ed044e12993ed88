#include "geometry/beam_tree.hpp"

#include "optics/light.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cmath>
#include <utility>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace airlight::geometry {
namespace {

using Side = BeamTree::Side;

// Far enough that every backplate lies outside the soups' box [-3, 3]³ seen from any light here.
constexpr double kFar = 8.0;

// The way a light travels, unit in double (the scene's float vector is unit to 6·10⁻⁸).
glm::dvec3 travel(const Light& light) { return glm::normalize(glm::dvec3(light.direction)); }

// ---- Lights ----

struct LightCase {
  std::string name;
  Light light;
};

Light spot(const glm::dvec3& position, const glm::dvec3& axis, float cone_deg) {
  Light light;
  light.type = LightType::spot;
  light.position = position;
  light.direction = glm::normalize(axis);
  light.cone_deg = cone_deg;
  return light;
}

std::vector<LightCase> light_cases() {
  Light point;
  point.position = {0.4f, 0.7f, -0.3f};
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.beam = Beam{-6.0f * sun.direction, {5.0f, 4.5f}, 12.0f};
  return {{"point", point},
          {"spot30", spot({0.5, 2.6, 0.2}, {-0.1, -1.0, 0.05}, 30.0f)},
          {"spot100", spot({-0.3, 0.1, 0.6}, {0.3, 0.2, -1.0}, 100.0f)},
          {"beam", sun}};
}

// ---- Polygon measures ----

glm::dvec3 twice_area(const std::vector<glm::dvec3>& v) {
  glm::dvec3 sum(0.0);
  for (size_t i = 1; i + 1 < v.size(); ++i) sum += glm::cross(v[i] - v[0], v[i + 1] - v[0]);
  return sum;
}

double area(const std::vector<glm::dvec3>& v) { return 0.5 * glm::length(twice_area(v)); }

// Van Oosterom and Strackee's solid angle of a triangle seen from the origin, unsigned.
double solid_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double det = std::abs(glm::dot(a, glm::cross(b, c)));
  return 2.0 * std::atan2(det, la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la);
}

// How much of the light's influence a polygon covers: a point light's solid angle, a
// directional light's area across D.
double coverage(const Light& light, const std::vector<glm::dvec3>& v) {
  if (light.type == LightType::directional) return 0.5 * std::abs(glm::dot(twice_area(v), travel(light)));
  const glm::dvec3 l(light.position);
  double sum = 0.0;
  for (size_t i = 1; i + 1 < v.size(); ++i) sum += solid_angle(v[0] - l, v[i] - l, v[i + 1] - l);
  return sum;
}

// Where the ray origin + t·dir, t > 0, meets a convex polygon, and how far inside it
// (negative: outside); nothing when the ray misses its plane or the polygon has no area.
struct Crossing {
  double t;
  double inside;
};
std::optional<Crossing> crossing(const std::vector<glm::dvec3>& v, const glm::dvec3& origin, const glm::dvec3& dir) {
  const glm::dvec3 normal = twice_area(v);
  if (glm::length(normal) == 0.0) return std::nullopt;
  const glm::dvec3 n = glm::normalize(normal);
  const double t = glm::dot(n, v[0] - origin) / glm::dot(n, dir);
  if (!(t > 0.0)) return std::nullopt;
  const glm::dvec3 x = origin + t * dir;
  double inside = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 edge = v[(i + 1) % v.size()] - v[i];
    if (glm::length(edge) > 0.0) inside = std::min(inside, glm::dot(glm::normalize(glm::cross(n, edge)), x - v[i]));
  }
  return Crossing{t, inside};
}

// ---- Small scenes worked by hand ----

BeamPolygon square_at(double z, double half, int source) {
  return {{{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}}, source};
}

double area_of(const std::vector<BeamPolygon>& polygons, int source) {
  double sum = 0.0;
  for (const BeamPolygon& polygon : polygons) sum += polygon.source == source ? area(polygon.vertices) : 0.0;
  return sum;
}

// Areas here are sums of a few fan cross products of coordinates ≤ 4 m: rounding 10⁻¹⁴ m².
constexpr double kAreaRounding = 1e-12;

TEST(BeamTree, SquareOverAFloorShadowsItsProjectionFromAPoint) {
  Light light;
  light.position = {0.0f, 0.0f, 2.0f};
  const std::vector<BeamPolygon> scene = {square_at(0.0, 1.0, 0), square_at(-1.0, 4.0, 1)};
  const double epsilon = beam_epsilon(light_origin(light), scene);
  const BeamTree tree(light_origin(light), scene, epsilon);

  // From z = 2 the square's edges x, y = ±1 at z = 0 reach ±(2 − z)/2: ±1.25 at z = −0.5,
  // ±1.5 on the floor.
  EXPECT_EQ(tree.classify({0, 0, 1}), Side::lit);
  EXPECT_EQ(tree.classify({0, 0, -0.5}), Side::shadowed);
  EXPECT_EQ(tree.classify({3, 0, -0.5}), Side::lit);
  EXPECT_EQ(tree.classify({1.25 + 1e-3, 0.3, -0.5}), Side::lit);
  EXPECT_EQ(tree.classify({1.25 - 1e-3, 0.3, -0.5}), Side::shadowed);
  EXPECT_EQ(tree.classify({1.25, 0.3, -0.5}), Side::boundary);  // on the plane through L and x = 1
  EXPECT_EQ(tree.classify({0.5, 0.5, 0}), Side::boundary);      // on the square
  EXPECT_EQ(tree.classify({3, 0, -2}), Side::shadowed);         // under the floor
  EXPECT_EQ(tree.classify({10, 0, -2}), Side::lit);             // beyond the floor's beam

  // Seen from L: all of the square, the floor less the square's shadow [−1.5, 1.5]².
  EXPECT_NEAR(area_of(tree.visible_set(), 0), 4.0, kAreaRounding);
  EXPECT_NEAR(area_of(tree.visible_set(), 1), 64.0 - 9.0, kAreaRounding);
  // The square: 4 planes, each with an open leaf, and its solid leaf, under the root. The floor
  // reaches the 4 open leaves as 4 pieces, which have 3, 2, 2 and 1 edges that no plane holds:
  // 8 more planes with their open leaves.
  EXPECT_EQ(tree.node_count(), 1 + 2 * 4 + 2 * 8);

  std::vector<BeamPolygon> lit, shadowed;
  tree.partition(square_at(-0.5, 4.0, 7), lit, shadowed);
  EXPECT_NEAR(area_of(shadowed, 7), 2.5 * 2.5, kAreaRounding);
  EXPECT_NEAR(area_of(lit, 7), 64.0 - 2.5 * 2.5, kAreaRounding);
}

TEST(BeamTree, SquareOverAFloorShadowsItsOwnShapeAlongD) {
  Light light;
  light.type = LightType::directional;
  light.direction = {0.0f, 0.0f, -1.0f};
  const std::vector<BeamPolygon> scene = {square_at(0.0, 1.0, 0), square_at(-1.0, 4.0, 1)};
  const BeamTree tree(light_origin(light), scene, beam_epsilon(light_origin(light), scene));
  EXPECT_EQ(tree.classify({0.99, 0, -0.5}), Side::shadowed);
  EXPECT_EQ(tree.classify({1.01, 0, -0.5}), Side::lit);
  EXPECT_EQ(tree.classify({0, 0, 5}), Side::lit);
  EXPECT_NEAR(area_of(tree.visible_set(), 1), 64.0 - 4.0, kAreaRounding);
  std::vector<BeamPolygon> lit, shadowed;
  tree.partition(square_at(-0.5, 4.0, 7), lit, shadowed);
  EXPECT_NEAR(area_of(shadowed, 7), 4.0, kAreaRounding);
}

TEST(BeamTree, SkipsASliverWhoseSideOfThePointLightRoundingHides) {
  // A sliver 2 m long and 2·10⁻⁹ wide, 10⁻⁴ from L: its normal may be off by about
  // 10⁻¹⁶·2/(2·10⁻⁹) rad, L's height over its plane by 10⁻⁷ m. At 10⁻⁹ m L's side is
  // unknown (skipped); at 10⁻³ m it is not (kept). With ε = 10⁻⁹ neither is narrower than ε
  // nor thinner than ε seen from L.
  Light light;
  light.position = {0.0f, 0.0f, 0.0f};
  for (const double height : {1e-9, 1e-3}) {
    const std::vector<BeamPolygon> sliver = {{{{1e-4, 0, height}, {2, 0, height}, {1, 2e-9, height}}, 0}};
    const BeamTree tree(light_origin(light), sliver, 1e-9);
    EXPECT_EQ(tree.stats().zero_area, 0) << height;
    EXPECT_EQ(tree.stats().edge_on, height < 1e-6) << height;
    EXPECT_EQ(tree.visible_set().size(), height < 1e-6 ? 0u : 1u) << height;
  }
}

TEST(BeamTree, RefusesNonFiniteAndNonPlanarPolygonsAndABadEpsilon) {
  Light light;
  const LightOrigin origin = light_origin(light);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<BeamPolygon> non_finite = {{{{0, 0, 1}, {1, 0, 1}, {0, nan, 1}}, 0}};
  EXPECT_THROW(BeamTree(origin, non_finite, 1e-6), Failure);
  std::vector<BeamPolygon> bent = {square_at(-1.0, 1.0, 0)};
  bent[0].vertices[2].z += 1e-3;  // 10³ times ε off the others' plane
  EXPECT_THROW(BeamTree(origin, bent, 1e-6), Failure);
  for (const double epsilon : {0.0, -1e-6, nan, std::numeric_limits<double>::infinity()})
    EXPECT_THROW(BeamTree(origin, {}, epsilon), Failure) << epsilon;
}

// ---- The backplate ----

// Whether the ray from `origin` along `dir` meets one of the faces. A base circumscribing a
// cone touches the rim's rays at its edges' midpoints, so up to rounding at 8 m (10⁻¹⁴ m).
bool meets(const std::vector<BeamPolygon>& faces, const glm::dvec3& origin, const glm::dvec3& dir) {
  return std::any_of(faces.begin(), faces.end(), [&](const BeamPolygon& face) {
    const std::optional<Crossing> c = crossing(face.vertices, origin, dir);
    return c && c->inside >= -1e-12;
  });
}

TEST(BeamTree, BackplateClosesEveryLightsInfluence) {
  const glm::dvec3 position(0.3, -0.2, 0.5);
  Light point;
  point.position = position;
  const std::vector<BeamPolygon> cube = influence_backplate(point, kFar);
  ASSERT_EQ(cube.size(), 6u);
  double total = 0.0;
  for (const BeamPolygon& face : cube) {
    EXPECT_EQ(face.source, -1);
    total += coverage(point, face.vertices);
  }
  EXPECT_NEAR(total, 4.0 * std::numbers::pi, 1e-12);  // rounding of six atan2

  // A spot's faces are those its cone reaches; every direction on the cone's rim meets one.
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.2, -1.0, 0.3));
  for (const auto& [cone, faces] : {std::pair(30.0f, 1u), std::pair(45.0f, 1u), std::pair(60.0f, 5u),
                                    std::pair(125.0f, 5u), std::pair(126.0f, 6u), std::pair(180.0f, 6u)}) {
    const Light light = spot(position, axis, cone);
    const std::vector<BeamPolygon> backplate = influence_backplate(light, kFar);
    EXPECT_EQ(backplate.size(), faces) << cone;
    glm::dvec3 right, up;
    optics::gobo_frame(light, right, up);
    const double angle = std::min(cone * std::numbers::pi / 180.0, std::numbers::pi - 1e-9);
    for (int k = 0; k < 360; ++k) {
      const double around = 2.0 * std::numbers::pi * k / 360.0;
      const glm::dvec3 dir =
          std::cos(angle) * travel(light) + std::sin(angle) * (std::cos(around) * right + std::sin(around) * up);
      EXPECT_TRUE(meets(backplate, glm::dvec3(light.position), dir)) << cone << "° at " << k << "°";
    }
  }
  // The 30° spot's base circumscribes the cone: half-size far·tan 30°, 4·asin(sin² 30°) sr.
  EXPECT_NEAR(coverage(spot(position, axis, 30.0f), influence_backplate(spot(position, axis, 30.0f), kFar)[0].vertices),
              4.0 * std::asin(0.25), 1e-12);

  // A beam: the far face of its box, the aperture moved `length` downstream.
  const Light beam = light_cases()[3].light;
  const std::vector<BeamPolygon> far_face = influence_backplate(beam, kFar);
  ASSERT_EQ(far_face.size(), 1u);
  EXPECT_NEAR(coverage(beam, far_face[0].vertices), 5.0 * 4.5, 1e-12);
  glm::dvec3 centre(0.0);
  for (const glm::dvec3& x : far_face[0].vertices) centre += 0.25 * x;
  EXPECT_NEAR(glm::distance(centre, glm::dvec3(beam.beam->origin) + 12.0 * travel(beam)), 0.0, 1e-12);

  // An unbounded directional light: a square 2·far wide, far downstream of the origin.
  Light sun = beam;
  sun.beam.reset();
  const std::vector<BeamPolygon> sun_face = influence_backplate(sun, kFar);
  ASSERT_EQ(sun_face.size(), 1u);
  EXPECT_NEAR(coverage(sun, sun_face[0].vertices), 4.0 * kFar * kFar, 1e-12);
}

}  // namespace
}  // namespace airlight::geometry
