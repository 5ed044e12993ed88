#include "scene/gobo_patterns.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

namespace airlight {
namespace {

using scene_gobo::glass_colors;

bool in_unit_range(const Image& image) {
  for (const glm::vec3& p : image.pixels)
    for (int c = 0; c < 3; ++c)
      if (!(p[c] >= 0.0f && p[c] <= 1.0f)) return false;
  return true;
}

double mean_red(const Image& image) {
  double sum = 0.0;
  for (const glm::vec3& p : image.pixels) sum += p.r;
  return sum / double(image.pixels.size());
}

double fraction_where(const Image& image, auto predicate) {
  size_t count = 0;
  for (const glm::vec3& p : image.pixels) count += predicate(p);
  return double(count) / double(image.pixels.size());
}

bool mirror_symmetric(const Image& image) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (glm::length(image.at(x, y) - image.at(image.width - 1 - x, y)) > 1e-5f) return false;
  return true;
}

bool dark(const glm::vec3& p) { return glm::length(p) < 0.05f; }

TEST(GoboPatterns, PolkaDotsCoverTheirAreaWithWhiteDotsOnBlack) {
  const Image dots = scene_gobo::polka_dots(64, 4, 0.6f);
  ASSERT_EQ(dots.width, 64);
  ASSERT_EQ(dots.height, 64);
  EXPECT_TRUE(in_unit_range(dots));
  // Each lattice cell holds a disc of diameter 0.6 pitches: coverage π/4 · 0.6².
  EXPECT_NEAR(mean_red(dots), glm::quarter_pi<double>() * 0.36, 0.01);
  for (const glm::vec3& p : dots.pixels) EXPECT_TRUE(p.r == p.g && p.g == p.b) << "dots are white";
  EXPECT_EQ(dots.at(8, 8), glm::vec3(1.0f)) << "a dot's centre";
  EXPECT_EQ(dots.at(0, 0), glm::vec3(0.0f)) << "between dots";
  EXPECT_TRUE(mirror_symmetric(dots));
}

TEST(GoboPatterns, PolkaDotEdgesAreAntialiased) {
  const Image dots = scene_gobo::polka_dots(64, 4, 0.6f);
  const double partial = fraction_where(dots, [](const glm::vec3& p) { return p.r > 0.0f && p.r < 1.0f; });
  EXPECT_GT(partial, 0.02);
  EXPECT_LT(partial, 0.25);
}

TEST(GoboPatterns, StainedGlassHasSaturatedPanesBetweenDarkLead) {
  const Image glass = scene_gobo::stained_glass(128, 128);
  ASSERT_EQ(glass.width, 128);
  ASSERT_EQ(glass.height, 128);
  EXPECT_TRUE(in_unit_range(glass));
  EXPECT_TRUE(mirror_symmetric(glass));
  // The lead border: every edge texel is black.
  for (int k = 0; k < 128; ++k) {
    EXPECT_TRUE(dark(glass.at(k, 0)) && dark(glass.at(k, 127)));
    EXPECT_TRUE(dark(glass.at(0, k)) && dark(glass.at(127, k)));
  }
  // Lead lines take a visible but minor share; the rest is glass.
  const double lead = fraction_where(glass, dark);
  EXPECT_GT(lead, 0.12);
  EXPECT_LT(lead, 0.35);
  for (const glm::vec3& color : glass_colors) {
    const double share =
        fraction_where(glass, [&](const glm::vec3& p) { return glm::length(p - color) < 1e-4f; });
    EXPECT_GT(share, 0.04) << "every glass colour is used";
  }
}

TEST(GoboPatterns, GlassColorsAreSaturated) {
  for (const glm::vec3& c : glass_colors) {
    const float hi = std::max({c.r, c.g, c.b}), lo = std::min({c.r, c.g, c.b});
    EXPECT_GT(hi, 0.6f);
    EXPECT_LT(lo, 0.1f);
  }
}

}  // namespace
}  // namespace airlight
