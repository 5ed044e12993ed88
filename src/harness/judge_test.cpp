// The harness's measures on images made by hand: each bound is met or missed
// where the arithmetic says, and a bad value fails before any measure.
#include "harness/judge.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace airlight::harness {
namespace {

Image flat(float value) { return Image(4, 3, glm::vec3(value)); }

TEST(Judge, RelRmseIsTheRootMeanSquareOverTheMean) {
  Image method = flat(1.0f);
  method.at(0, 0) = glm::vec3(1.0f + std::sqrt(12.0f));  // one pixel of 12 off by √12: RMSE 1
  EXPECT_NEAR(rel_rmse(method, exactly(flat(1.0f))), 1.0, 1e-6);
  EXPECT_NEAR(rel_rmse(flat(1.0f), exactly(flat(2.0f))), 0.5, 1e-6);  // RMSE 1 over a mean of 2
}

TEST(Judge, RelRmseOfABlackReferenceDividesByTheFloor) {
  EXPECT_NEAR(rel_rmse(flat(1e-7f), exactly(flat(0.0f))), 1e-7 / absolute_floor, 1e-6);
}

TEST(Judge, WorstPixelSkipsPixelsBelowOnePercentOfTheMaximum) {
  Image reference = flat(1.0f), method = flat(1.0f);
  reference.at(1, 1) = glm::vec3(0.009f);  // below 1 % of the maximum: not judged however wrong
  method.at(1, 1) = glm::vec3(5.0f);
  reference.at(2, 1) = glm::vec3(0.011f);  // above it: judged by its own value
  method.at(2, 1) = glm::vec3(0.011f * 1.5f);
  const WorstPixel w = worst_pixel(method, exactly(reference));
  EXPECT_EQ(w.x, 2);
  EXPECT_EQ(w.y, 1);
  EXPECT_NEAR(w.error, 0.5, 1e-5);
}

TEST(Judge, WorstPixelTakesTheLargestChannelErrorOverTheLargestChannel) {
  Image reference(1, 1, glm::vec3(1.0f, 0.1f, 0.1f)), method(1, 1, glm::vec3(1.0f, 0.1f, 0.13f));
  EXPECT_NEAR(worst_pixel(method, exactly(reference)).error, 0.03, 1e-6);  // 0.03 of the red, not 30 % of the blue
}

TEST(Judge, BadValuesAreNamedWithTheirPixel) {
  Image image = flat(1.0f);
  EXPECT_EQ(bad_value(image), "");
  image.at(3, 2).g = -0.5f;
  EXPECT_EQ(bad_value(image), "pixel (3, 2) is negative (-0.5)");
  image.at(1, 0).b = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(bad_value(image), "pixel (1, 0) is NaN");
  image.at(0, 0).r = std::numeric_limits<float>::infinity();
  EXPECT_EQ(bad_value(image), "pixel (0, 0) is infinite");
}

TEST(Judge, DefaultsWithinTenPercent) {
  EXPECT_TRUE(judge_defaults(flat(1.09f), exactly(flat(1.0f))).pass);
  const Verdict v = judge_defaults(flat(1.11f), exactly(flat(1.0f)));
  EXPECT_FALSE(v.pass);
  EXPECT_EQ(v.measure, "rel_rmse");
  EXPECT_EQ(v.detail, "rRMSE 0.11 > 0.1");
}

TEST(Judge, WithoutLightsOnlyZeroPasses) {
  EXPECT_TRUE(judge_defaults(flat(0.0f), exactly(flat(0.0f))).pass);
  const Verdict v = judge_defaults(flat(1e-9f), exactly(flat(0.0f)));
  EXPECT_FALSE(v.pass);
  EXPECT_EQ(v.detail, "airlight 1e-09 where the reference has none");
}

TEST(Judge, ANanFailsBeforeAnyMeasure) {
  Image method = flat(1.0f);
  method.at(0, 0).r = std::numeric_limits<float>::quiet_NaN();
  const Trial trial{"exact", {}, Trial::Measure::worst_pixel, 0.02, "test"};
  const Verdict v = judge_trial(trial, method, exactly(flat(1.0f)));
  EXPECT_FALSE(v.pass);
  EXPECT_EQ(v.measure, "finite");
  EXPECT_EQ(v.trial, "exact");
}

TEST(Judge, TrialsUseTheirMeasureAndBound) {
  const Trial worst{"exact", {}, Trial::Measure::worst_pixel, 0.02, "test"};
  Image method = flat(1.0f);
  method.at(2, 2) = glm::vec3(1.03f);
  const Verdict v = judge_trial(worst, method, exactly(flat(1.0f)));
  EXPECT_FALSE(v.pass);
  EXPECT_EQ(v.detail, "pixel (2, 2): 1.03 against 1, error 0.03 > 0.02");
  const Trial rmse{"high quality", {}, Trial::Measure::rel_rmse, 0.03, "test"};
  EXPECT_TRUE(judge_trial(rmse, method, exactly(flat(1.0f))).pass);  // 0.03/√12 overall
}

// A silhouette crossing a pixel close to its centre: the shifted rays see 0.2
// or 1.2 where the centre's sees 1; a method may give either, and is judged
// by how far it lies outside them, over the larger of the centre's value and
// the bracket's end it passed.
TEST(Judge, APixelIsJudgedByItsBracket) {
  Image shifted_low = flat(1.0f), shifted_high = flat(1.0f);
  shifted_low.at(1, 1) = glm::vec3(0.2f);
  shifted_high.at(1, 1) = glm::vec3(1.2f);
  const Reference r = bracket({flat(1.0f), shifted_low, flat(1.0f), shifted_high});
  EXPECT_EQ(r.centre.at(1, 1), glm::vec3(1.0f));
  EXPECT_EQ(r.low.at(1, 1), glm::vec3(0.2f));
  EXPECT_EQ(r.high.at(1, 1), glm::vec3(1.2f));
  Image method = flat(1.0f);
  method.at(1, 1) = glm::vec3(0.25f);
  EXPECT_EQ(worst_pixel(method, r).error, 0.0);
  EXPECT_EQ(rel_rmse(method, r), 0.0);
  method.at(1, 1) = glm::vec3(1.5f);  // 0.3 above the bracket, over its top 1.2
  EXPECT_NEAR(worst_pixel(method, r).error, 0.25, 1e-6);
  method.at(1, 1) = glm::vec3(0.1f);  // 0.1 below it, over the centre's 1 (the larger)
  EXPECT_NEAR(worst_pixel(method, r).error, 0.1, 1e-6);
  const Trial worst{"exact", {}, Trial::Measure::worst_pixel, 0.02, "test"};
  EXPECT_EQ(judge_trial(worst, method, r).detail,
            "pixel (1, 1): 0.1 against 1 (0.2 to 1.2 near the pixel's centre), error 0.1 > 0.02");
}

// Beside a light's image (random scene 314): the centre's ray sees 0.118, a
// shifted one 8.742; a method's 8.757 is 0.17 % past what the pixel may hold,
// not 13 % of the centre.
TEST(Judge, APixelBesideALightIsJudgedByTheBrightEnd) {
  Image centre = flat(1.0f), shifted = flat(1.0f);
  centre.at(1, 1) = glm::vec3(0.118f);
  shifted.at(1, 1) = glm::vec3(8.742f);
  Image method = centre;
  method.at(1, 1) = glm::vec3(8.757f);
  EXPECT_NEAR(worst_pixel(method, bracket({centre, shifted})).error, 0.015 / 8.742, 1e-5);
}

// Shifted rays are traced where a neighbour differs by more than an eighth:
// the step's two sides, not the smooth rest.
TEST(Judge, ABaselineWidensTheBracket) {
  Image reference(2, 1), baseline(2, 1), method(2, 1);
  reference.pixels = {glm::vec3(1.0f), glm::vec3(1.0f)};
  baseline.pixels = {glm::vec3(2.0f), glm::vec3(0.5f)};
  const Reference r = widened(exactly(reference), baseline);
  EXPECT_EQ(r.low.pixels[0], glm::vec3(1.0f));
  EXPECT_EQ(r.high.pixels[0], glm::vec3(2.0f));
  EXPECT_EQ(r.low.pixels[1], glm::vec3(0.5f));
  EXPECT_EQ(r.high.pixels[1], glm::vec3(1.0f));
  EXPECT_EQ(r.centre.pixels[0], glm::vec3(1.0f));  // the scale stays the reference's
  method.pixels = {glm::vec3(1.5f), glm::vec3(0.4f)};
  EXPECT_NEAR(worst_pixel(method, r).error, 0.1, 1e-6);  // 0.1 below 0.5, over the centre's 1
}

TEST(Judge, SharpPixelsAreThoseBesideAStep) {
  Image centre = flat(1.0f);
  centre.at(0, 0) = glm::vec3(1.01f);  // a hundredth: smooth
  centre.at(3, 2) = glm::vec3(2.0f);  // a step
  const std::vector<bool> sharp = sharp_pixels(centre);
  const auto at = [&](int x, int y) { return bool(sharp[static_cast<size_t>(y * 4 + x)]); };
  EXPECT_FALSE(at(0, 0));
  EXPECT_FALSE(at(1, 1));
  EXPECT_TRUE(at(3, 2));
  EXPECT_TRUE(at(2, 1));  // beside it: 1 against 2
  EXPECT_FALSE(at(1, 0));
}

TEST(Judge, TheReferenceAgainstBruteForceAtItsPixels) {
  Image reference = flat(1.0f);
  reference.at(1, 1) = glm::vec3(2.0f);
  const std::vector<glm::ivec2> pixels{{1, 1}, {0, 0}};
  EXPECT_TRUE(judge_reference(reference, pixels, {glm::dvec3(2.0), glm::dvec3(1.001)}).pass);
  const Verdict v = judge_reference(reference, pixels, {glm::dvec3(2.0), glm::dvec3(1.01)});
  EXPECT_FALSE(v.pass);
  EXPECT_EQ(v.detail, "pixel (0, 0): reference 1 against brute force 1.01, error 0.009901");
  // A dark pixel is judged against a thousandth of the image's maximum (0.002):
  // 2e-6 off is 1e-3 of that, not 100 % of itself.
  reference.at(2, 2) = glm::vec3(0.0f);
  EXPECT_TRUE(judge_reference(reference, {{2, 2}}, {glm::dvec3(2e-6)}).pass);
  EXPECT_FALSE(judge_reference(reference, {{2, 2}}, {glm::dvec3(1e-5)}).pass);  // 5e-3 of it
}

}  // namespace
}  // namespace airlight::harness
