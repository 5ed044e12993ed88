// beam_volumes (Nilsson 2008 §3.2) against the CPU reference (docs/design.md
// §6): exact shadows from the beam tree's pyramids with the eye inside the lit
// volume, and what Nilsson's signed accumulation loses to float cancellation
// where a light is in view.
#include "core/metrics.hpp"
#include "methods/kit/test_support.hpp"

#include <airlight/method.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace airlight::methods {
namespace {

using namespace kit::test;

constexpr int width = 128, height = 96;

FrameImages beam_volumes(const Scene& scene, const std::vector<std::string>& settings = {}) {
  return kit::test::render(find_method("beam_volumes"), scene, settings, width, height);
}

TEST(BeamVolumes, RegisteredWithItsSettings) {
  std::set<std::string> names;
  for (const SettingSpec& s : find_method("beam_volumes").settings) names.insert(s.name);
  EXPECT_EQ(names, (std::set<std::string>{"shadow_resolution", "shadow_bias", "capacity", "samples", "accumulate"}));
}

// The eye inside the spot's lit cone of biri_sphere, between the light and the
// sphere's shadow, looking down through it: the count starts at 0.
TEST(BeamVolumes, CameraInsideTheLitVolume) {
  Scene scene = builtin_scene("biri_sphere");
  scene.name = "biri_sphere_eye_lit";
  scene.camera.position = {0.6f, 4.0f, 0.8f};
  scene.camera.look_at = {0.0f, 1.0f, 0.0f};
  const FrameImages frame = beam_volumes(scene);
  const ImageError e = compare_images(frame.airlight, fine_reference_airlight(scene, width, height));
  std::printf("eye in the lit volume: rRMSE %.5f, max abs %.5f\n", e.rel_rmse, e.max_abs);
  EXPECT_LT(e.rel_rmse, 0.01);  // exact shadows: Γ and the reference's quadrature
  EXPECT_GT(stat(frame, "beam_tree_nodes"), 0.0);
  EXPECT_GT(stat(frame, "visible_polygons"), 0.0);
}

// Nilsson's signed sum against the counted intervals, with the spot's apex in
// view close up (biri_sphere's light seen from 2 m): Σ ±Γ(0 → z) over a
// pixel's faces cancels terms up to the largest Γ(0 → z) of the pixel, so its
// float error is at most 2^-23 · Σ_k |Γ(0 → z_k)| (docs/decisions.md); the
// intervals integrate each lit stretch directly. Both stay far inside 1%
// here, and each pixel's error is its own (a crack between faces costs one pixel).
TEST(BeamVolumes, SignedSumAndIntervalsAgreeWithALightInView) {
  Scene scene = builtin_scene("biri_sphere");
  scene.name = "biri_sphere_apex";
  scene.camera.position = {0.6f, 4.0f, 2.0f};
  scene.camera.look_at = {0.0f, 4.5f, 0.0f};
  const Image ref = fine_reference_airlight(scene, width, height);
  const ImageError counted = compare_images(beam_volumes(scene).airlight, ref);
  const ImageError summed = compare_images(beam_volumes(scene, {"accumulate=signed"}).airlight, ref);
  std::printf("apex in view: intervals rRMSE %.6f max abs %.6f, signed rRMSE %.6f max abs %.6f\n", counted.rel_rmse,
              counted.max_abs, summed.rel_rmse, summed.max_abs);
  EXPECT_LT(counted.rel_rmse, 0.01);  // exact shadows: Γ and the reference's quadrature
  EXPECT_LT(summed.rel_rmse, 0.01);
}

TEST(BeamVolumes, AirlightPassDrawsNoShadowMap) {
  const Scene scene = builtin_scene("biri_sphere");
  auto method = prepared(find_method("beam_volumes"), scene, {});
  std::vector<std::string> passes;
  for (const auto& t : airlight::render(*method, scene, 32, 24, false).times) passes.push_back(t.pass);
  EXPECT_EQ(passes, (std::vector<std::string>{"gbuffer", "crossings", "airlight"}));
}

}  // namespace
}  // namespace airlight::methods
