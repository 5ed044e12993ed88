// harness/random.hpp: PCG32 and splitmix64 against their published outputs, and
// the distributions' ranges and rough uniformity.
#include "harness/random.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <vector>

namespace airlight::harness {
namespace {

// pcg32-demo.c of the reference C implementation, seeded with 42 and sequence 54:
// the first line it prints.
TEST(Random, Pcg32GivesTheReferenceCodesOutputs) {
  Random random(42u, 54u);
  for (const std::uint32_t expected : {0xa15c02b7u, 0x7b47f409u, 0xba1d3330u, 0x83d2f293u, 0xbfa4784bu, 0xcbed606eu})
    EXPECT_EQ(random.next(), expected);
}

// Vigna's splitmix64.c started at 1234567: its first two outputs.
TEST(Random, Splitmix64GivesTheReferenceCodesOutputs) {
  EXPECT_EQ(splitmix64(1234567u, 1), 6457827717110365317ull);
  EXPECT_EQ(splitmix64(1234567u, 2), 3203168211198807973ull);
}

TEST(Random, ASeedGivesOneSequenceAndNeighbouringSeedsOthers) {
  Random a(7), b(7), c(8);
  std::vector<std::uint32_t> first;
  for (int i = 0; i < 16; ++i) first.push_back(a.next());
  for (int i = 0; i < 16; ++i) EXPECT_EQ(b.next(), first[i]);
  int same = 0;
  for (int i = 0; i < 16; ++i) same += c.next() == first[i];
  EXPECT_EQ(same, 0);
}

constexpr int kDraws = 100000;
// A bin of kDraws/10 draws has a standard deviation of about sqrt(kDraws/10) = 100:
// 5 of them is beyond chance for a fixed seed, so a bias this small would show.
constexpr double kBinSlack = 500.0;

void expect_uniform_bins(const std::array<int, 10>& bins) {
  for (const int n : bins) EXPECT_NEAR(n, kDraws / 10.0, kBinSlack);
}

TEST(Random, UniformStaysInItsRangeAndFillsItEvenly) {
  Random random(1);
  std::array<int, 10> bins{};
  for (int i = 0; i < kDraws; ++i) {
    const double x = random.uniform(-2.0, 3.0);
    ASSERT_GE(x, -2.0);
    ASSERT_LT(x, 3.0);
    ++bins[static_cast<size_t>((x + 2.0) / 0.5)];
  }
  expect_uniform_bins(bins);
}

TEST(Random, IntegerTakesEveryValueOfItsRangeEvenly) {
  Random random(2);
  std::array<int, 10> bins{};
  for (int i = 0; i < kDraws; ++i) {
    const int k = random.integer(-3, 6);
    ASSERT_GE(k, -3);
    ASSERT_LE(k, 6);
    ++bins[static_cast<size_t>(k + 3)];
  }
  expect_uniform_bins(bins);
  EXPECT_EQ(random.integer(5, 5), 5);
}

TEST(Random, LogUniformFillsEveryDecadeEvenly) {
  Random random(3);
  std::array<int, 10> bins{};
  for (int i = 0; i < kDraws; ++i) {
    const double x = random.log_uniform(1e-3, 1e7);
    ASSERT_GE(x, 1e-3 * (1 - 1e-12));  // exp(log(lo)) may round a hair below lo
    ASSERT_LT(x, 1e7 * (1 + 1e-12));
    ++bins[static_cast<size_t>(std::clamp(std::floor(std::log10(x)) + 3.0, 0.0, 9.0))];
  }
  expect_uniform_bins(bins);
}

// Unit length, and every octant of the sphere equally likely (8 bins; the
// first 8 of expect_uniform_bins' 10 would not do, so counted here).
TEST(Random, UnitVectorsAreUnitAndCoverTheSphereEvenly) {
  Random random(4);
  std::array<int, 8> octants{};
  glm::dvec3 sum(0.0);
  for (int i = 0; i < kDraws; ++i) {
    const glm::dvec3 v = random.unit_vector();
    ASSERT_NEAR(glm::length(v), 1.0, 1e-12);  // rounding of sqrt, cos and sin
    ++octants[(v.x > 0) + 2 * (v.y > 0) + 4 * (v.z > 0)];
    sum += v;
  }
  for (const int n : octants) EXPECT_NEAR(n, kDraws / 8.0, kBinSlack);
  // The mean of kDraws unit vectors has a standard deviation of 1/sqrt(3·kDraws) ≈ 0.0018 per axis.
  EXPECT_LT(glm::length(sum / double(kDraws)), 0.01);
}

TEST(Random, BernoulliAndPickFollowTheirOdds) {
  Random random(5);
  int heads = 0;
  for (int i = 0; i < kDraws; ++i) heads += random.bernoulli(0.3);
  EXPECT_NEAR(heads, 0.3 * kDraws, kBinSlack);  // standard deviation sqrt(0.21·kDraws) ≈ 145
  EXPECT_FALSE(random.bernoulli(0.0));
  EXPECT_TRUE(random.bernoulli(1.0));
  const std::array<int, 10> items{0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
  std::array<int, 10> bins{};
  for (int i = 0; i < kDraws; ++i) ++bins[static_cast<size_t>(random.pick(std::span<const int>(items)))];
  expect_uniform_bins(bins);
}

}  // namespace
}  // namespace airlight::harness
