// Reduced resolution's plumbing (kit/resolution): which methods take it, what
// a frame runs at each scale, and what it costs in memory. Its images against
// the reference are each method's Reduced rows (testing/reduced_quality.hpp).
#include "methods/kit/testing/test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace airlight::kit::test {
namespace {

bool declares_scale(const MethodInfo& info) {
  return std::any_of(info.settings.begin(), info.settings.end(), [](const SettingSpec& s) { return s.name == "scale"; });
}

std::set<std::string> pass_names(const FrameImages& frame) {
  std::set<std::string> names;
  for (const PassTime& t : frame.times) names.insert(t.pass);
  return names;
}

// The methods that evaluate the airlight per pixel take `scale`; those that
// draw planes through the volume (their cost is not per pixel) do not.
TEST(ReducedResolution, EveryPerPixelMethodTakesScale) {
  std::set<std::string> with;
  for (const MethodInfo& info : registered_methods())
    if (declares_scale(info)) with.insert(info.name);
  EXPECT_EQ(with, (std::set<std::string>{"raymarch", "interleaved", "analytic", "sv_march", "shadow_planes",
                                         "beam_volumes", "light_volume"}));
}

// scale = 1 runs none of the reduced resolution's passes (the frame is the one
// before it, docs/decisions.md "Reduced resolution"); 1/4 runs all three, and
// bilinear upsampling has nothing to merge.
TEST(ReducedResolution, PassesAtEachScale) {
  const Scene scene = builtin_scene("teapot_spot");
  const std::set<std::string> own{"downsample", "upsample", "merge"};
  for (const MethodInfo& info : registered_methods()) {
    if (!declares_scale(info)) continue;
    SCOPED_TRACE(info.name);
    auto ran = [&](std::vector<std::string> settings) {
      std::set<std::string> names = pass_names(render(info, scene, settings, 32, 24)), hit;
      std::set_intersection(names.begin(), names.end(), own.begin(), own.end(), std::inserter(hit, hit.end()));
      return hit;
    };
    EXPECT_EQ(ran({"scale=1"}), std::set<std::string>{});
    EXPECT_EQ(ran({"scale=1/4"}), own);
    EXPECT_EQ(ran({"scale=1/4", "upsample=bilinear"}), (std::set<std::string>{"downsample", "upsample"}));
  }
}

// The estimate counts the coarse grid's textures and, with bilateral
// upsampling, the full grid's textures and lists, a halo's included: 20 bytes
// a coarse pixel, 28 a pixel, 4 a 2×2 block and two lists' headers of 16.
TEST(ReducedResolution, MemoryEstimateCountsItsTextures) {
  const Scene scene = builtin_scene("teapot_spot");
  const MethodInfo& info = find_method("raymarch");
  auto bytes = [&](std::vector<std::string> assignments) {
    Settings settings(info.settings);
    for (const auto& a : assignments) settings.set(a, "test");
    double sum = 0.0;
    for (const MemoryNeed& need : info.memory(scene, settings, 1000, 600)) sum += need.bytes;
    return sum;
  };
  EXPECT_DOUBLE_EQ(bytes({"scale=1/2"}) - bytes({"scale=1"}), 20.0 * 500 * 300 + 28.0 * 1000 * 600 + 4.0 * 500 * 300 + 32.0);
  EXPECT_DOUBLE_EQ(bytes({"scale=1/4", "upsample=bilinear"}) - bytes({"scale=1"}), 20.0 * 250 * 150);
}

}  // namespace
}  // namespace airlight::kit::test
