// PNG tone curves (docs/decisions.md "PNG tone mapping") against their published
// formulas, evaluated here independently on grey inputs, and auto exposure.
#include "core/tonemap.hpp"

#include "core/image_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

namespace airlight {
namespace {

constexpr ToneCurve curves[] = {ToneCurve::agx, ToneCurve::aces, ToneCurve::clamp};

double srgb(double c) {  // IEC 61966-2-1, written out again
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
}

int byte(float encoded) { return static_cast<int>(std::lround(255.0f * encoded)); }

// The display luminance a viewer sees: the encoded values decoded to linear.
float shown_luminance(glm::vec3 radiance, ToneCurve curve) {
  const glm::vec3 e = tone_map(radiance, {1.0f, curve});
  return luminance({srgb_to_linear(e.r), srgb_to_linear(e.g), srgb_to_linear(e.b)});
}

TEST(ToneMap, EveryCurveIsMonotonicInLuminanceFrom1eMinus4To1e4) {
  for (ToneCurve curve : curves)
    for (glm::vec3 color : {glm::vec3(1.0f), glm::vec3(1.0f, 0.6f, 0.25f), glm::vec3(0.1f, 0.3f, 1.0f)}) {
      const float first = shown_luminance(color * 1e-4f, curve);
      float highest = first, y = first;
      for (int i = 1; i <= 160; ++i) {  // 20 steps a decade
        const float scale = std::pow(10.0f, -4.0f + i / 20.0f);
        y = shown_luminance(color * scale, curve);
        // 1e-3, a ninth of the 8-bit step at white (0.0089 linear): as a saturated colour
        // reaches white, AgX's outset matrix gives back up to 2.4e-4 of luminance.
        EXPECT_GE(y, highest - 1e-3f) << tone_curve_name(curve) << " at " << scale;
        highest = std::max(highest, y);
      }
      EXPECT_GT(y, first + 0.5f) << tone_curve_name(curve);  // and it does rise, from near black to near white
    }
}

TEST(ToneMap, BlackStaysBlack) {
  for (ToneCurve curve : curves)
    EXPECT_EQ(tone_map(glm::vec3(0.0f), {1.0f, curve}), glm::vec3(0.0f)) << tone_curve_name(curve);
}

TEST(ToneMap, AgxAndAcesRollOffWhereClampClips) {
  auto grey = [](float v, ToneCurve curve) { return tone_map(glm::vec3(v), {1.0f, curve}).g; };
  for (float v : {10.0f, 100.0f, 1000.0f}) EXPECT_LT(grey(v, ToneCurve::agx), 1.0f) << v;
  for (ToneCurve curve : {ToneCurve::agx, ToneCurve::aces}) {
    EXPECT_LT(byte(grey(1.0f, curve)), byte(grey(10.0f, curve))) << tone_curve_name(curve);
    EXPECT_LT(byte(grey(10.0f, curve)), byte(grey(100.0f, curve))) << tone_curve_name(curve);
  }
  EXPECT_EQ(byte(grey(1.0f, ToneCurve::clamp)), 255);  // today's behaviour: a lamp core is flat white
  EXPECT_EQ(byte(grey(10.0f, ToneCurve::clamp)), 255);
}

// Wrensch's sigmoid fit as published, summed term by term (the code uses Horner form).
double agx_polynomial(double x) {
  return 15.5 * std::pow(x, 6) - 40.14 * std::pow(x, 5) + 31.96 * std::pow(x, 4) - 6.868 * std::pow(x, 3) +
         0.4298 * x * x + 0.1191 * x - 0.00232;
}

TEST(ToneMap, AgxSigmoidIsTheFitsPolynomial) {
  // 1e-6: float evaluation of a polynomial whose terms reach ±15.
  for (double x : {0.0, 0.25, 0.5, 20.0 / 33.0, 0.75, 1.0})
    EXPECT_NEAR(agx_contrast(float(x)), agx_polynomial(x), 1e-6) << x;
  EXPECT_NEAR(agx_contrast(0.0f), -0.00232, 1e-7);     // its black level, clipped to 0 after the outset
  EXPECT_NEAR(agx_contrast(1.0f), 0.99858, 1e-6);      // the sum of the coefficients: white stays below 1
  EXPECT_NEAR(agx_contrast(20.0f / 33.0f), 0.49673, 1e-5);  // mid grey sits at x = 10/16.5
}

// Grey through AgX: the matrices' rows sum to 1 within 2e-4, so grey stays grey and
// the curve is log2 encoding, sigmoid, 2.2 power, sRGB.
double agx_grey(double v) {
  const double x = std::clamp((std::log2(v) + 12.47393) / (4.026069 + 12.47393), 0.0, 1.0);
  return srgb(std::pow(std::max(agx_polynomial(x), 0.0), 2.2));
}

// Hill's RRT+ODT fit on grey (its matrices' rows sum to 1 within 1e-5), input /0.6.
double aces_grey(double v) {
  const double x = v / 0.6;
  return srgb((x * (x + 0.0245786) - 0.000090537) / (x * (0.983729 * x + 0.4329510) + 0.238081));
}

TEST(ToneMap, GreyFollowsThePublishedCurves) {
  for (double v : {0.001, 0.01, 0.18, 1.0, 4.0, 10.0}) {
    const glm::vec3 agx = tone_map(glm::vec3(float(v)), {1.0f, ToneCurve::agx});
    const glm::vec3 aces = tone_map(glm::vec3(float(v)), {1.0f, ToneCurve::aces});
    // 5e-4: the rows' sums (within 2e-4 of 1) and float arithmetic.
    EXPECT_NEAR(agx.g, agx_grey(v), 5e-4) << v;
    EXPECT_NEAR(aces.g, aces_grey(v), 5e-4) << v;
    EXPECT_NEAR(agx.r, agx.b, 5e-4) << v;  // still grey
    EXPECT_NEAR(aces.r, aces.b, 5e-4) << v;
  }
  // Mid grey 0.18 shows as sRGB 0.50 (code 128) under AgX, 0.499 under ACES; clamp gives 0.46.
  EXPECT_NEAR(tone_map(glm::vec3(0.18f), {1.0f, ToneCurve::agx}).g, 0.5005, 5e-4);
  EXPECT_EQ(byte(tone_map(glm::vec3(0.18f), {1.0f, ToneCurve::agx}).g), 128);
  EXPECT_NEAR(tone_map(glm::vec3(0.18f), {1.0f, ToneCurve::aces}).g, 0.4990, 5e-4);
  EXPECT_NEAR(aces_grey(0.6), srgb(0.619115), 1e-6);  // Hill's fit at 1: 1.0244881 / 1.6547610
  // Exposure multiplies first.
  EXPECT_EQ(tone_map(glm::vec3(0.09f), {2.0f, ToneCurve::agx}), tone_map(glm::vec3(0.18f), {1.0f, ToneCurve::agx}));
}

TEST(ToneMap, NonFiniteAndNegativeRadianceNeverReachAPng) {
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (ToneCurve curve : curves) {
    EXPECT_EQ(tone_map(glm::vec3(nan), {1.0f, curve}), glm::vec3(0.0f)) << tone_curve_name(curve);
    EXPECT_EQ(tone_map(glm::vec3(-5.0f), {1.0f, curve}), glm::vec3(0.0f)) << tone_curve_name(curve);
    const glm::vec3 bright = tone_map(glm::vec3(inf), {1.0f, curve});
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(std::isfinite(bright[c])) << tone_curve_name(curve);
      EXPECT_GT(bright[c], 0.99f) << tone_curve_name(curve);
    }
  }
  Image image(2, 1);
  image.at(0, 0) = glm::vec3(nan);
  image.at(1, 0) = glm::vec3(inf);
  const auto file = std::filesystem::temp_directory_path() / "airlight_tonemap_nan.png";
  write_image(image, file);
  const Image back = read_image(file);
  EXPECT_EQ(back.at(0, 0), glm::vec3(0.0f));
  EXPECT_GT(back.at(1, 0).g, 0.99f);
  std::filesystem::remove(file);
}

TEST(AutoExposure, MapsTheLogAverageLuminanceToTheKey) {
  const glm::vec3 color(0.1f, 0.05f, 0.02f);
  const float y = luminance(color);
  // 1e-4 relative: δ = 1e-6 in log(δ + Y) shifts the average by δ/Y = 2e-5.
  EXPECT_NEAR(auto_exposure(Image(8, 4, color)), 0.18f / y, 1e-4f * 0.18f / y);
  // The log average is the geometric mean: half the pixels 0.01, half 1 average 0.1.
  Image halves(8, 4, glm::vec3(0.01f));
  for (int x = 0; x < 4; ++x)
    for (int row = 0; row < 4; ++row) halves.at(x, row) = glm::vec3(1.0f);
  EXPECT_NEAR(auto_exposure(halves), 1.8f, 1.8f * 1e-3f);  // 1e-3: δ/0.01 = 1e-4 plus float log sums
}

TEST(AutoExposure, IgnoresBlackAndNonFinitePixels) {
  Image image(4, 4, glm::vec3(0.05f));
  image.at(0, 0) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
  image.at(1, 0) = glm::vec3(std::numeric_limits<float>::infinity());
  image.at(2, 0) = glm::vec3(0.0f);
  EXPECT_NEAR(auto_exposure(image), 3.6f, 3.6f * 1e-4f);  // 0.18 / 0.05; 1e-4 as above
  EXPECT_EQ(auto_exposure(Image(4, 4)), 1.0f);              // all black: nothing to measure
}

TEST(ToneMap, CurveNames) {
  for (ToneCurve curve : curves) EXPECT_EQ(tone_curve(tone_curve_name(curve)), curve);
  EXPECT_EQ(tone_curve("filmic"), std::nullopt);
}

}  // namespace
}  // namespace airlight
