#include "scene/mesh_build.hpp"
#include "scene/shapes.hpp"
#include "scene/test_support.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

namespace airlight {
namespace {

using namespace scene_mesh;
using scene_test::closed_after_welding;
using scene_test::misoriented_fraction;
using scene_test::signed_volume;
using scene_test::well_formed;

TEST(Shapes, BoxIsClosedWithFlatOutwardFaces) {
  const Mesh box = make_box({-1, 0, -2}, {1, 3, 2});
  ASSERT_TRUE(well_formed(box));
  EXPECT_EQ(box.positions.size(), 24u);
  EXPECT_EQ(box.triangles.size(), 12u);
  EXPECT_EQ(misoriented_fraction(box), 0.0);
  EXPECT_NEAR(signed_volume(box), 2.0 * 3.0 * 4.0, 1e-4);
  EXPECT_TRUE(closed_after_welding(box));  // as the floor slabs and walls of the built-in scenes
}

TEST(Shapes, SphereIsClosedRoundAndOutward) {
  const glm::vec3 center(1, 2, 3);
  const Mesh sphere = make_sphere(center, 0.5f, 48);
  ASSERT_TRUE(well_formed(sphere));
  EXPECT_EQ(sphere.triangles.size(), 2u * 48u * 23u);
  EXPECT_EQ(misoriented_fraction(sphere), 0.0);
  EXPECT_TRUE(closed_after_welding(sphere));
  for (size_t i = 0; i < sphere.positions.size(); ++i) {
    EXPECT_NEAR(glm::distance(sphere.positions[i], center), 0.5f, 1e-5f);
    EXPECT_GT(glm::dot(sphere.normals[i], glm::normalize(sphere.positions[i] - center)), 0.9999f);
  }
  const double exact = 4.0 / 3.0 * glm::pi<double>() * 0.125;
  EXPECT_NEAR(signed_volume(sphere) / exact, 1.0, 0.01);
}

TEST(Shapes, SphereWith32SegmentsHasA32EdgeEquator) {
  const Mesh sphere = make_sphere({0, 0, 0}, 1.0f, 32);
  size_t on_equator = 0;
  for (const glm::vec3& p : sphere.positions) on_equator += std::fabs(p.y) < 1e-6f;
  EXPECT_EQ(on_equator, 32u);
}

TEST(Shapes, PlaneFacesItsNormalWithTheGivenSize) {
  const glm::vec3 normal = glm::normalize(glm::vec3(0, 1, 1));
  const Mesh plane = make_plane({0, 1, 0}, {4, 2}, normal);
  ASSERT_TRUE(well_formed(plane));
  ASSERT_EQ(plane.triangles.size(), 2u);
  EXPECT_EQ(misoriented_fraction(plane), 0.0);
  EXPECT_FALSE(closed_after_welding(plane));  // one-sided by design
  for (const glm::uvec3& t : plane.triangles) {
    const glm::vec3 n = face_normal(plane.positions[t.x], plane.positions[t.y], plane.positions[t.z]);
    EXPECT_GT(glm::dot(n, normal), 0.9999f);
  }
  // The x extent stays along world x (the shortest rotation from +y keeps x).
  EXPECT_NEAR(glm::distance(plane.positions[0], plane.positions[3]), 4.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(plane.positions[0], plane.positions[1]), 2.0f, 1e-5f);
}

TEST(Shapes, PlaneFacingDownIsHalfTurnAboutX) {
  const Mesh plane = make_plane({0, 0, 0}, {2, 2}, {0, -1, 0});
  ASSERT_TRUE(well_formed(plane));
  EXPECT_EQ(misoriented_fraction(plane), 0.0);
  const glm::uvec3 t = plane.triangles[0];
  EXPECT_LT(face_normal(plane.positions[t.x], plane.positions[t.y], plane.positions[t.z]).y,
            -0.9999f);
  // A half turn about x keeps the plane's x edge along +x.
  EXPECT_NEAR(plane.positions[3].x - plane.positions[0].x, 2.0f, 1e-6f);
}

TEST(Shapes, CylinderIsClosedAndHasTheRightVolume) {
  const Mesh cylinder = make_cylinder({0, 1, 0}, 0.5f, 2.0f, 64);
  ASSERT_TRUE(well_formed(cylinder));
  EXPECT_EQ(misoriented_fraction(cylinder), 0.0);
  EXPECT_TRUE(closed_after_welding(cylinder));
  const double exact = glm::pi<double>() * 0.25 * 2.0;
  EXPECT_NEAR(signed_volume(cylinder) / exact, 1.0, 0.01);
  for (const glm::vec3& p : cylinder.positions) {
    EXPECT_GE(p.y, 1.0f - 1e-6f);
    EXPECT_LE(p.y, 3.0f + 1e-6f);
  }
}

TEST(Shapes, ArchIsClosedOutwardAndStandsOnItsFeet) {
  const glm::vec3 center(1, 2, -1);
  const Mesh arch = make_arch(center, 0.8f, 1.2f, 0.5f, 24);
  ASSERT_TRUE(well_formed(arch));
  EXPECT_EQ(arch.triangles.size(), 8u * 24u + 4u);
  EXPECT_EQ(misoriented_fraction(arch), 0.0);
  EXPECT_TRUE(closed_after_welding(arch));
  const double exact = 0.5 * glm::pi<double>() * (1.2 * 1.2 - 0.8 * 0.8) * 0.5;
  EXPECT_NEAR(signed_volume(arch) / exact, 1.0, 0.01);
  for (const glm::vec3& p : arch.positions) {
    EXPECT_GE(p.y, center.y);
    const float r = glm::length(glm::vec2(p - center));
    EXPECT_TRUE(std::fabs(r - 0.8f) < 1e-5f || std::fabs(r - 1.2f) < 1e-5f) << r;
    EXPECT_NEAR(std::fabs(p.z - center.z), 0.25f, 1e-6f);
  }
}

TEST(Shapes, TransformScalesThenRotatesXYZThenTranslates) {
  Transform t;
  t.scale = 2.0f;
  t.rotate_deg = {90, 90, 0};  // X first: +y -> +z; then Y: +z -> +x
  t.translate = {0, 0, 5};
  Mesh mesh = make_plane({0, 1, 0}, {1, 1}, {0, 1, 0});
  apply(t, mesh);
  ASSERT_TRUE(well_formed(mesh));
  for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::distance(n, glm::vec3(1, 0, 0)), 0.0f, 1e-6f);
  glm::vec3 centroid(0.0f);
  for (const glm::vec3& p : mesh.positions) centroid += p / 4.0f;
  EXPECT_NEAR(glm::distance(centroid, glm::vec3(2, 0, 5)), 0.0f, 1e-5f);
}

TEST(Shapes, WeldMergesCoincidentVerticesAndDropsCollapsedTriangles) {
  MeshBuilder b;
  const uint32_t a = b.vertex({0, 0, 0}, {0, 0, 1}), c = b.vertex({1, 0, 0}, {0, 0, 1});
  const uint32_t d = b.vertex({0, 1, 0}, {0, 0, 1}), e = b.vertex({1e-7f, 0, 0}, {1, 0, 1});
  b.triangle(a, c, d);
  b.triangle(e, c, d);  // the same triangle through a near-duplicate of a
  Mesh mesh = b.take("test");
  weld(mesh, 1e-5f);
  EXPECT_EQ(mesh.positions.size(), 3u);
  EXPECT_EQ(mesh.triangles.size(), 2u);
  ASSERT_TRUE(well_formed(mesh));
}

TEST(Shapes, CapHolesClosesEachLoopFacingOut) {
  // A box without its y faces: a square tube with two square holes.
  Mesh tube = make_box({-1, 0, -2}, {1, 3, 2});
  tube.triangles.erase(tube.triangles.begin() + 4, tube.triangles.begin() + 8);
  weld(tube, 1e-5f);
  ASSERT_FALSE(closed_after_welding(tube));
  cap_holes(tube);
  ASSERT_TRUE(well_formed(tube));
  EXPECT_TRUE(closed_after_welding(tube));
  EXPECT_EQ(tube.triangles.size(), 8u + 2u * 4u);  // a fan of 4 per hole
  EXPECT_EQ(misoriented_fraction(tube), 0.0);
  EXPECT_NEAR(signed_volume(tube), 2.0 * 3.0 * 4.0, 1e-4);  // as the box's
  int up = 0, down = 0;
  for (const glm::vec3& n : tube.normals) {
    up += n == glm::vec3(0, 1, 0);
    down += n == glm::vec3(0, -1, 0);
  }
  EXPECT_EQ(up, 5);  // each cap's centre and its own copies of the hole's 4 corners
  EXPECT_EQ(down, 5);
}

TEST(Shapes, BuilderRefusesDegenerateTriangles) {
  MeshBuilder b;
  const uint32_t a = b.vertex({0, 0, 0}, {0, 0, 1}), c = b.vertex({1, 0, 0}, {0, 0, 1});
  const uint32_t d = b.vertex({2, 0, 0}, {0, 0, 1});
  b.triangle(a, c, d);
  b.triangle(a, a, c);
  EXPECT_TRUE(b.mesh().triangles.empty());
}

// The slabs of a room fill the shell between the inside and the inside grown by
// the wall's thickness, all but the window's opening through the back wall:
// their volumes add up to the shell's, so none overlaps another or leaves a gap.
TEST(Shapes, RoomSlabsFillItsShellButTheWindow) {
  const Extent inside{{-4, 0, -3}, {4, 3.5f, 3}}, window{{-0.8f, 1, -3.25f}, {0.8f, 3, -3}};
  const float wall = 0.25f;
  const auto volume = [](const glm::vec3& min, const glm::vec3& max) {
    const glm::vec3 d = max - min;
    return double(d.x) * d.y * d.z;
  };
  const double shell = volume(inside.min - wall, inside.max + wall) - volume(inside.min, inside.max);
  for (const bool with_window : {false, true}) {
    const std::vector<Mesh> room = make_room(inside, with_window ? std::optional(window) : std::nullopt, wall);
    EXPECT_EQ(room.size(), with_window ? 9u : 6u);
    double sum = 0.0;
    for (const Mesh& piece : room) {
      EXPECT_TRUE(well_formed(piece) && closed_after_welding(piece)) << piece.name;
      sum += signed_volume(piece);
    }
    EXPECT_NEAR(sum, shell - (with_window ? volume(window.min, window.max) : 0.0), 1e-3);
  }
  EXPECT_EQ(make_room(inside, window, wall).back().name, "wall right of window");
}

// A column stands on the floor and reaches `height`; a table's top is at its
// given centre and its legs stand on the floor.
TEST(Shapes, ColumnAndTableStandOnTheFloor) {
  const auto bounds = [](const std::vector<Mesh>& pieces) {
    glm::vec2 y(1e9f, -1e9f);
    for (const Mesh& m : pieces)
      for (const glm::vec3& p : m.positions) y = {std::min(y[0], p.y), std::max(y[1], p.y)};
    return y;
  };
  const std::vector<Mesh> column = make_column({1, 2}, 4.6f, 16);
  ASSERT_EQ(column.size(), 3u);
  EXPECT_EQ(column[1].name, "column");
  EXPECT_EQ(bounds(column), glm::vec2(0.0f, 4.6f));
  const std::vector<Mesh> table = make_table({0.1f, 0.75f, -1.3f}, {1.2f, 0.7f});
  ASSERT_EQ(table.size(), 5u);  // the top and four legs
  EXPECT_EQ(bounds(table), glm::vec2(0.0f, 0.75f));
  EXPECT_EQ(table.front().name, "table top");
}

}  // namespace
}  // namespace airlight
