#pragma once
// The quality contract (docs/design.md §6): a method against `reference` on the
// airlight pass. Each method's folder has its rows (<method>_quality.cpp), every
// tolerance beside its reason, and instantiates the harness below with them:
// INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name).
// Include it from one file per test program.
#include "core/metrics.hpp"
#include "methods/kit/test_support.hpp"

#include <airlight/method.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>

namespace airlight::kit::test {

inline constexpr int width = 128, height = 96;  // small: the whole table runs in seconds

struct Case {
  const char* method;
  const char* scene;
  std::vector<std::string> settings;
  double max_rel_rmse;
  const char* reason;
};


// A case's scene: a built-in, or a file under bench/scenes/ (a name ending in .json).
inline Scene case_scene(const std::string& name) {
  if (name.ends_with(".json")) return load_scene(std::filesystem::path(AIRLIGHT_BENCH_SCENES) / name);
  return builtin_scene(name);
}

inline FrameImages render_case(const std::string& method_name, const Scene& scene, const std::vector<std::string>& assignments) {
  return render(find_method(method_name), scene, assignments, width, height);
}

inline const Image& reference_airlight(const std::string& scene_name) {
  static std::map<std::string, Image> cache;
  auto it = cache.find(scene_name);
  if (it == cache.end()) it = cache.emplace(scene_name, render_case("reference", case_scene(scene_name), {}).airlight).first;
  return it->second;
}

class Quality : public ::testing::TestWithParam<Case> {};

TEST_P(Quality, AirlightWithinTolerance) {
  const Case& c = GetParam();
  const Image& expected = reference_airlight(c.scene);
  const FrameImages frame = render_case(c.method, case_scene(c.scene), c.settings);
  const ImageError e = compare_images(frame.airlight, expected);
  std::printf("%s on %s: rRMSE %.4f (bound %.3f), max abs %.4f\n", c.method, c.scene, e.rel_rmse, c.max_rel_rmse,
              e.max_abs);
  EXPECT_LT(e.rel_rmse, c.max_rel_rmse) << c.reason;
}

inline std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string name = std::string(info.param.method) + "_" + info.param.scene;
  for (const auto& s : info.param.settings) name += "_" + s;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

}  // namespace airlight::kit::test
