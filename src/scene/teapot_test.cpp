#include "scene/shapes.hpp"
#include "scene/test_support.hpp"

#include <algorithm>
#include <gtest/gtest.h>
#include <map>

namespace airlight {
namespace {

using namespace scene_mesh;
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

// Edge -> how many triangles use it, and with which orientation (+1 for a→b
// with a < b, −1 for the reverse).
struct EdgeUse {
  int count = 0, orientation = 0;
};

std::map<std::pair<uint32_t, uint32_t>, EdgeUse> edge_uses(const Mesh& mesh) {
  std::map<std::pair<uint32_t, uint32_t>, EdgeUse> uses;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = t[k], b = t[(k + 1) % 3];
      EdgeUse& use = uses[{std::min(a, b), std::max(a, b)}];
      ++use.count;
      use.orientation += a < b ? 1 : -1;
    }
  return uses;
}

TEST(Teapot, IsWellFormed) {
  const Mesh teapot = make_teapot(8);
  ASSERT_TRUE(well_formed(teapot));
  // 32 patches of 8×8 quads, less the pole-collapsed triangles of 8 patches.
  EXPECT_EQ(teapot.triangles.size(), 32u * 128u - 8u * 8u);
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

TEST(Teapot, IsClosedIshAndConsistentlyWound) {
  const Mesh teapot = make_teapot(8);
  size_t boundary = 0, inconsistent = 0, non_manifold = 0;
  const auto uses = edge_uses(teapot);
  for (const auto& [edge, use] : uses) {
    boundary += use.count == 1;
    non_manifold += use.count > 2;
    inconsistent += use.count == 2 && use.orientation != 0;
  }
  // Open only where the data is: the lid/rim gap, the spout's ends and the
  // handle's ends (8 segments each round): well under 5% of the edges.
  EXPECT_LT(double(boundary) / double(uses.size()), 0.05);
  EXPECT_EQ(non_manifold, 0u);
  EXPECT_EQ(inconsistent, 0u);
  EXPECT_GT(signed_volume(teapot), 0.0);  // wound outward
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
