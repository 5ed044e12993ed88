#include "scene/shapes.hpp"
#include "scene/test_support.hpp"

#include <gtest/gtest.h>

namespace airlight {
namespace {

using namespace scene_mesh;
using scene_test::closed_after_welding;
using scene_test::misoriented_fraction;
using scene_test::signed_volume;
using scene_test::well_formed;

struct Bounds {
  glm::vec3 min{1e30f}, max{-1e30f};
};

Bounds bounds(const Mesh& mesh) {
  Bounds b;
  for (const glm::vec3& p : mesh.positions) {
    b.min = glm::min(b.min, p);
    b.max = glm::max(b.max, p);
  }
  return b;
}

TEST(Teapot, IsWellFormed) {
  const Mesh teapot = make_teapot(8);
  ASSERT_TRUE(well_formed(teapot));
  // 32 patches of 8×8 quads, less the pole-collapsed triangles of 8 patches, plus a fan
  // triangle per edge of the six caps: the spout's and the handle's ends (2 patches' 8
  // segments each) and the lid's and the rim's edges (4 patches' 8 each).
  EXPECT_EQ(teapot.triangles.size(), 32u * 128u - 8u * 8u + 4u * 16u + 2u * 32u);
  EXPECT_LT(misoriented_fraction(teapot), 0.01);
}

TEST(Teapot, StandsOnTheFloorOneUnitTallSpoutTowardPlusX) {
  const Bounds b = bounds(make_teapot(8));
  EXPECT_NEAR(b.min.y, 0.0f, 1e-6f);
  EXPECT_NEAR(b.max.y, 1.0f, 1e-6f);
  // Spout tip at x ≈ 3.43, handle at x ≈ −3.0, body radius 2 in the data's units.
  EXPECT_NEAR(b.max.x, 3.43f / 3.15f, 0.02f);
  EXPECT_NEAR(b.min.x, -3.0f / 3.15f, 0.02f);
  EXPECT_NEAR(b.max.z, 2.0f / 3.15f, 0.002f);
  EXPECT_NEAR(b.min.z, -2.0f / 3.15f, 0.002f);
}

// The patches' seams share vertices and the six holes are capped: closed, every edge run
// once each way, which also rules out inconsistent winding and non-manifold edges.
TEST(Teapot, IsClosedAfterWeldingByPosition) {
  for (const int n : {2, 3, 8, 16}) {
    const Mesh teapot = make_teapot(n);
    EXPECT_TRUE(closed_after_welding(teapot)) << n;
    EXPECT_GT(signed_volume(teapot), 0.0) << n;  // wound outward
  }
}

// The caps are the triangles whose three vertex normals are one (the smooth patches' differ).
// Each hole's rim is a plane curve (its control points lie in a plane), so a cap is flat:
// its triangles' face normals are its normal to float rounding, far inside the 0.8° that
// 0.9999 allows (which also holds the axis-aligned caps to their axes). Facing out of what they close:
// up from the rim's gap and the spout's tip, down under the lid, back (−x) from the spout's
// base, forward (+x, into the body) from the handle's ends.
TEST(Teapot, CapsAreFlatAndFaceOutward) {
  const Mesh teapot = make_teapot(8);
  int up = 0, down = 0, back = 0, forward = 0, caps = 0;
  for (const glm::uvec3& t : teapot.triangles) {
    const glm::vec3 n = teapot.normals[t.x];
    if (n != teapot.normals[t.y] || n != teapot.normals[t.z]) continue;
    ++caps;
    EXPECT_GT(glm::dot(face_normal(teapot.positions[t.x], teapot.positions[t.y], teapot.positions[t.z]), n),
              0.9999f);
    up += n.y > 0.9999f;
    down += n.y < -0.9999f;
    back += n.x < -0.9999f;
    forward += n.x > 0.9f;  // the handle's ends lean 18° and 24° off +x
  }
  EXPECT_EQ(caps, 128);
  EXPECT_EQ(up, 32 + 16);
  EXPECT_EQ(down, 32);
  EXPECT_EQ(back, 16);
  EXPECT_EQ(forward, 16 + 16);
}

TEST(Teapot, PoleNormalsPointUpAndDown) {
  const Mesh teapot = make_teapot(8);
  for (size_t i = 0; i < teapot.positions.size(); ++i) {
    const glm::vec3& p = teapot.positions[i];
    if (glm::length(glm::vec2(p.x, p.z)) > 1e-6f) continue;
    if (p.y > 0.99f) {
      EXPECT_GT(teapot.normals[i].y, 0.999f);  // lid knob
    } else if (p.y < 0.01f) {
      EXPECT_LT(teapot.normals[i].y, -0.999f);  // bottom
    }
  }
}

TEST(Teapot, FinerTessellationStaysWellFormed) {
  for (const int n : {2, 3, 16}) EXPECT_TRUE(well_formed(make_teapot(n))) << n;
}

}  // namespace
}  // namespace airlight
