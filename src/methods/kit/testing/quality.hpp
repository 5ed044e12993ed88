#pragma once
// The quality contract (docs/design.md §6): a method against `reference` on the
// airlight pass. Each method's folder has its rows (<method>_quality.cpp), every
// tolerance beside its reason, and instantiates the harness below with them:
// INSTANTIATE_TEST_SUITE_P(Table, Quality, ::testing::ValuesIn(rows), case_name).
// Include it from one file per test program.
#include "core/metrics.hpp"
#include "core/test_paths.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <airlight/method.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <ostream>

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
  if (name.ends_with(".json")) return load_scene(airlight::test::bench_scenes() / name);
  return builtin_scene(name);
}

inline FrameImages render_case(const std::string& method_name, const Scene& scene,
                               const std::vector<std::string>& assignments) {
  return render(find_method(method_name), scene, assignments, width, height);
}

inline Image reference_airlight(const std::string& scene_name) {
  return shared_reference(case_scene(scene_name), width, height).airlight;
}

// A second frame with everything moved (docs/design.md §3: no new prepare):
// the camera, every light and every mesh turned 25° about the vertical and
// shifted by (0.7, 0.2, −0.4) m. Every per-frame input changes — the camera,
// the light records and shadow projections, the object transforms, planes' lit
// regions — yet the scene relative to the camera does not, so each row's
// reason for its tolerance still holds: a piece of state left from the first
// frame shows as an error far above it. (Bounded volumes are fixed at prepare
// and stay; no row's scene has one.)
inline FrameInputs moved_inputs(const Scene& scene) {
  FrameInputs in = frame_inputs(scene, width, height);
  const glm::mat4 motion = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.7f, 0.2f, -0.4f)),
                                       glm::radians(25.0f), glm::vec3(0, 1, 0));
  const auto point = [&](const glm::vec3& p) { return glm::vec3(motion * glm::vec4(p, 1.0f)); };
  const auto vector = [&](const glm::vec3& v) { return glm::vec3(motion * glm::vec4(v, 0.0f)); };
  in.camera.position = point(in.camera.position);
  in.camera.look_at = point(in.camera.look_at);
  in.camera.up = vector(in.camera.up);
  for (Light& light : in.lights) {
    light.position = point(light.position);
    light.direction = vector(light.direction);
    light.gobo_up = vector(light.gobo_up);
    if (light.beam) light.beam->origin = point(light.beam->origin);
  }
  in.transforms.assign(scene.meshes.size(), motion);
  return in;
}

inline void expect_within(const Case& c, const Image& image, const Image& expected, const char* what) {
  const ImageError e = compare_images(image, expected);
  std::printf("%s on %s%s: rRMSE %.4f (bound %.3f), max abs %.4f\n", c.method, c.scene, what, e.rel_rmse,
              c.max_rel_rmse, e.max_abs);
  EXPECT_LT(e.rel_rmse, c.max_rel_rmse) << c.reason;
}

// GoogleTest prints a case by its name, not its bytes.
inline void PrintTo(const Case& c, std::ostream* out) {
  *out << c.method << " on " << c.scene;
  for (const auto& s : c.settings) *out << " " << s;
}

class Quality : public ::testing::TestWithParam<Case> {};

// One prepared method, three frames, so that its programs compile once per row
// (README "Tests and their budget"): the first against the reference; a second
// with nothing changed, the same image bit for bit; then one with the camera, a
// light and an object moved, against the reference of the moved scene — the
// method is not prepared again.
TEST_P(Quality, FirstSecondAndMovedFrames) {
  const Case& c = GetParam();
  const Scene scene = case_scene(c.scene);
  auto method = prepared(find_method(c.method), scene, c.settings);
  const FrameImages first = render(*method, scene, width, height), second = render(*method, scene, width, height);
  expect_within(c, first.airlight, reference_airlight(c.scene), "");
  EXPECT_TRUE(first.airlight.pixels == second.airlight.pixels) << "the second frame's airlight differs";
  EXPECT_TRUE(first.surface.pixels == second.surface.pixels) << "the second frame's surface differs";
  const FrameInputs moved = moved_inputs(scene);
  method->render_frame(moved);
  const Image expected = shared_reference(posed_scene(scene, moved), width, height).airlight;
  expect_within(c, method->read_back().airlight, expected, " (moved)");
}

inline std::string case_name(const ::testing::TestParamInfo<Case>& info) {
  std::string name = std::string(info.param.method) + "_" + info.param.scene;
  for (const auto& s : info.param.settings) name += "_" + s;
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

}  // namespace airlight::kit::test
