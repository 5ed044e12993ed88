// sv_march (Kingston 2018 §4.3) against raymarch and the CPU reference
// (docs/design.md §6).
#include "core/metrics.hpp"
#include "gpu/program.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <airlight/method.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace airlight::methods {
namespace {

using namespace kit::test;

constexpr int width = 128, height = 96;

// rRMSE of `method` with `settings` against `reference` (each test renders its
// scene's reference once: it is the slow part).
double error_of(const char* method, const Scene& scene, const std::vector<std::string>& settings,
                const Image& reference) {
  return compare_images(kit::test::render(find_method(method), scene, settings, width, height).airlight, reference)
      .rel_rmse;
}

TEST(SvMarch, RegisteredWithItsSettings) {
  std::set<std::string> names;
  for (const SettingSpec& s : find_method("sv_march").settings) names.insert(s.name);
  EXPECT_EQ(names, (std::set<std::string>{"shadow_resolution", "shadow_bias", "steps", "jitter", "sampling",
                                          "volume_resolution", "samples", "scale", "upsample"}));
}

// The cold first frame's compile is paid per program (docs/decisions.md "The
// first frame (issue 28)"): on teapot_spot sv_march's first frame compiles the
// shared frame's background, G-buffer, shadow map and surface programs, the shell's five
// (cell depths, grid vertices, grid and strip triangles, eye count), the
// counted draw's cull and bounds draw, and its march: 12, and a second frame
// of the same structure none. A new variant shows here before it shows as
// seconds of a cold start. The march alone is linked ahead and warmed on the
// worker while the frame's passes run (GpuMethod::link_ahead): its link and
// code take the worker longer than all the rest takes the drawing thread,
// which links the shell's and the bounds draw's itself.
TEST(SvMarch, FirstFrameCompilesItsTwelvePrograms) {
  const Scene scene = builtin_scene("teapot_spot");
  gpu::clear_program_cache();
  const int ahead = gpu::linked_ahead_count(), warmed = gpu::warmed_count();
  kit::test::render(find_method("sv_march"), scene, {}, width, height);
  EXPECT_EQ(gpu::cached_program_count(), 12);
  EXPECT_EQ(gpu::linked_ahead_count(), ahead + 1) << "the march was not linked ahead";
  EXPECT_EQ(gpu::warmed_count(), warmed + 1) << "the march was not warmed on the worker";
  kit::test::render(find_method("sv_march"), scene, {}, width, height);
  EXPECT_EQ(gpu::cached_program_count(), 12) << "a second frame compiled a program";
}

// At equal steps N sv_march spends them on [front, back] alone and integrates
// the rest exactly: its error is at most raymarch's on the same maps, per
// scene at N = 4, 16 and 64 (measured 1.2–3× lower with the default 64² shell).
class SvMarchScenes : public ::testing::TestWithParam<const char*> {};

TEST_P(SvMarchScenes, NoWorseThanRaymarchAtEqualSteps) {
  const Scene scene = builtin_scene(GetParam());
  const Image reference = fine_reference_airlight(scene, width, height);
  for (const int n : {4, 16, 64}) {
    const std::string steps = "steps=" + std::to_string(n);
    const double sv = error_of("sv_march", scene, {steps}, reference);
    const double ray = error_of("raymarch", scene, {steps}, reference);
    std::printf("%s, N = %d: rRMSE sv_march %.5f, raymarch %.5f\n", GetParam(), n, sv, ray);
    EXPECT_LE(sv, ray) << n;
  }
}

// three_lights takes over 20 s with Mesa's shader cache off: both methods' programs
// for its three kinds of maps, at three N, and the fine reference (docs/decisions.md "Build").
INSTANTIATE_TEST_SUITE_P(Scenes, SvMarchScenes, ::testing::Values("teapot_spot", "biri_sphere", "three_lights"),
                         [](const auto& info) { return std::string(info.param); });

// The error falls as N grows, down to what the 1024² shadow map leaves along
// the teapot's shadow edges (raymarch at N = 256: 0.00063).
TEST(SvMarch, ConvergesToTheReference) {
  const Scene scene = builtin_scene("teapot_spot");
  const Image reference = fine_reference_airlight(scene, width, height);
  double previous = 1e30;
  for (const int n : {4, 16, 64, 256}) {
    const double e = error_of("sv_march", scene, {"steps=" + std::to_string(n)}, reference);
    std::printf("teapot_spot, N = %d: rRMSE %.5f\n", n, e);
    EXPECT_LT(e, previous) << n;
    previous = e;
  }
  EXPECT_LT(previous, 0.001);  // measured 0.00035
}

// biri_sphere seen from an eye moved to `position`, looking at `look_at`, at
// N = 16: no worse than raymarch, wherever the eye is.
void expect_eye_case(const char* name, glm::vec3 position, glm::vec3 look_at) {
  Scene scene = builtin_scene("biri_sphere");
  scene.name = name;
  scene.camera.position = position;
  scene.camera.look_at = look_at;
  const Image reference = fine_reference_airlight(scene, width, height);
  const double sv = error_of("sv_march", scene, {"steps=16"}, reference);
  const double ray = error_of("raymarch", scene, {"steps=16"}, reference);
  std::printf("%s, N = 16: rRMSE sv_march %.5f, raymarch %.5f\n", name, sv, ray);
  EXPECT_LE(sv, ray);
}

// In the spot's lit cone, between the light and the sphere's shadow, looking
// down through it: the shell ahead of the eye, lit before it.
TEST(SvMarch, CameraInsideTheLitVolume) {
  expect_eye_case("biri_sphere_eye_lit", {0.6f, 4.0f, 0.8f}, {0.0f, 1.0f, 0.0f});
}

// In the sphere's shadow, below it, looking past it at the cone: unlit before the shell.
TEST(SvMarch, CameraInsideAShadow) {
  expect_eye_case("biri_sphere_eye_shadowed", {0.1f, 2.0f, 0.1f}, {1.5f, 0.5f, 0.0f});
}

// On the sphere's shadow boundary (the cone of half-angle asin(1/3) from the
// light, 2.5 below it: radius 0.8839), inside the shell of the grid cells
// that straddle it (each about 0.01 wide there), looking across the beam: the
// march starts at the eye.
TEST(SvMarch, CameraInsideTheShell) {
  expect_eye_case("biri_sphere_eye_in_shell", {0.8839f, 2.0f, 0.0f}, {-1.5f, 1.0f, 0.0f});
}

}  // namespace
}  // namespace airlight::methods
