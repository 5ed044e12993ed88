#pragma once
// Reduced resolution against the reference (docs/design.md §3, §6): a
// method's rows at scale = 1/2, each tolerance beside its reason, in its
// <method>_quality.cpp after quality.hpp, instantiated with
// INSTANTIATE_TEST_SUITE_P(Reduced, ReducedQuality, ::testing::ValuesIn(rows), case_name).
#include "methods/kit/testing/quality.hpp"

namespace airlight::kit::test {

// The number of pixels whose airlight is the same in both images, bit for bit.
inline size_t same_pixels(const Image& a, const Image& b) {
  size_t same = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) same += a.pixels[i] == b.pixels[i] ? 1 : 0;
  return same;
}

class ReducedQuality : public ::testing::TestWithParam<Case> {};

// The row's settings at scale = 1/2 with bilateral upsampling, against the
// reference of what the method models (judged_scene: analytic's without its
// casters): within the row's bound; strictly
// better than plain bilinear upsampling of the same coarse image; with pixels
// recomputed (every scene here has silhouettes), and each recomputed pixel
// the full-scale frame's own, bit for bit.
TEST_P(ReducedQuality, HalfScaleAgainstReference) {
  const Case& c = GetParam();
  const Scene scene = case_scene(c.scene);
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> settings = c.settings;
    settings.insert(settings.end(), extra.begin(), extra.end());
    return render_case(c.method, scene, settings);
  };
  const FrameImages full = with({"scale=1"});
  const FrameImages bilateral = with({"scale=1/2", "upsample=bilateral"});
  const FrameImages bilinear = with({"scale=1/2", "upsample=bilinear"});
  const Image expected =
      shared_reference(judged_scene(scene, find_method(c.method).capabilities), width, height).airlight;
  expect_within(c, bilateral.airlight, expected, " at 1/2");
  std::printf("  full scale: rRMSE %.4f\n", compare_images(full.airlight, expected).rel_rmse);
  const double plain = compare_images(bilinear.airlight, expected).rel_rmse;
  std::printf("  bilinear: rRMSE %.4f\n", plain);
  EXPECT_LT(compare_images(bilateral.airlight, expected).rel_rmse, plain) << "no better than bilinear upsampling";
  const double fraction = stat(bilateral, "recomputed_fraction");
  std::printf("  recomputed: %.4f of the pixels\n", fraction);
  EXPECT_GT(fraction, 0.0) << "no pixel recomputed on a scene with silhouettes";
  EXPECT_GE(double(same_pixels(bilateral.airlight, full.airlight)), fraction * width * height)
      << "a recomputed pixel differs from the full-scale frame's";
}

}  // namespace airlight::kit::test
