// harness/sieve_scene: the million-triangle scene's count, rounded to whole
// tiles (its render at 10⁵: app/million_triangles_test.cpp).
#include "harness/sieve_scene.hpp"

#include <gtest/gtest.h>

namespace airlight::harness {
namespace {

TEST(SieveScene, RoundsToWholeTiles) {
  EXPECT_EQ(sieve_triangles(100000), 100000);
  EXPECT_EQ(sieve_triangles(1000399), 1000200);
  EXPECT_EQ(sieve_triangles(1), 200);
}

}  // namespace
}  // namespace airlight::harness
