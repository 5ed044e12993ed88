// light_volume (Billeter et al. 2010 after Kingston 2018) against the CPU
// reference (docs/design.md §6): exact up to the shadow map's resolution, so
// its error falls as the map's grows; the eye inside the lit volume and inside
// a shadow.
#include "core/metrics.hpp"
#include "core/warning.hpp"
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

// rRMSE against `reference` (rendered once per test: it is the slow part).
double error_of(const Scene& scene, const std::vector<std::string>& settings, const Image& reference) {
  const Image image = kit::test::render(find_method("light_volume"), scene, settings, width, height).airlight;
  return compare_images(image, reference).rel_rmse;
}

TEST(LightVolume, RegisteredWithItsSettings) {
  std::set<std::string> names;
  for (const SettingSpec& s : find_method("light_volume").settings) names.insert(s.name);
  EXPECT_EQ(names, (std::set<std::string>{"shadow_resolution", "shadow_bias", "volume_resolution", "capacity", "samples", "scale", "upsample"}));
}

// The mesh follows the map texel by texel, each all lit or all shadowed as
// the shadow test calls it: the error is the texels' along the teapot's
// shadow edges and falls as they shrink.
TEST(LightVolume, ErrorFallsWithTheMapsResolution) {
  const Scene scene = builtin_scene("teapot_spot");
  const Image reference = fine_reference_airlight(scene, width, height);
  double previous = 1e30;
  for (const int n : {128, 256, 512, 1024}) {
    const std::string r = std::to_string(n);
    const double e = error_of(scene, {"shadow_resolution=" + r, "volume_resolution=" + r}, reference);
    std::printf("teapot_spot, %d² map and volume: rRMSE %.5f\n", n, e);
    EXPECT_LT(e, previous) << n;
    previous = e;
  }
  // Measured 0.0025, 0.0012, 0.00067, 0.00029 (a height field through the
  // texels' depths: 0.0063, 0.0028, 0.0017, 0.0011): the texels along the
  // teapot's shadow edges. Twice the last.
  EXPECT_LT(previous, 0.0006);
}

// Issue 24: with its grid at the map's resolution the mesh is the map's own
// steps, every texel lit or shadowed exactly as the shadow test calls it, so
// light_volume must do no worse than raymarch at 256 steps on the same map
// (which reads that test at its samples). A height field through the texels'
// depths at the cells' corners, half a texel off the test, did worse (0.0049
// against 0.0034 on biri_sphere). Both renders are deterministic (raymarch's
// jitter is off): no tolerance.
// At a 128² map (the cheapest; measured 0.0123 against 0.0128 on
// biri_sphere, 0.0026 against 0.0028 on teapot_spot, 0.0031 against 0.0034 on
// three_lights; at 256² and 512² too, docs/decisions.md).
class LightVolumeScenes : public ::testing::TestWithParam<const char*> {};

constexpr int map_size = 128;

TEST_P(LightVolumeScenes, GridAtTheMapsResolutionNoWorseThanRaymarch256) {
  const Scene scene = builtin_scene(GetParam());
  const Image& reference = reference_airlight(scene, width, height);
  const std::string map = "shadow_resolution=" + std::to_string(map_size);
  const double volume = error_of(scene, {map, "volume_resolution=" + std::to_string(map_size)}, reference);
  const Image marched = render(find_method("raymarch"), scene, {map, "steps=256"}, width, height).airlight;
  const double raymarch = compare_images(marched, reference).rel_rmse;
  std::printf("%s, %d² map: light_volume (grid %d²) rRMSE %.5f, raymarch (256 steps) %.5f\n", GetParam(), map_size,
              map_size, volume, raymarch);
  EXPECT_LE(volume, raymarch);
}

INSTANTIATE_TEST_SUITE_P(Scenes, LightVolumeScenes, ::testing::Values("biri_sphere", "teapot_spot", "three_lights"),
                         [](const auto& info) { return std::string(info.param); });

// A cold first frame on three_lights links sixteen programs ahead
// (GpuMethod::link_ahead), each of them then used: the crossings' draw, the
// lit intervals' resolve, warmed, and the mesh's for a spot and for a
// directional map (grid vertices, extra vertices, grid and extra triangles,
// eye count) and for a cube (no extra vertices), each kind warmed together,
// by the worker or taken back by the build.
TEST(LightVolume, FirstFrameLinksAheadTheMeshOfEachKindOfLight) {
  gpu::clear_program_cache();
  const int ahead = gpu::linked_ahead_count(), warmed = gpu::warmed_count();
  kit::test::render(find_method("light_volume"), builtin_scene("three_lights"), {}, 32, 24);
  EXPECT_EQ(gpu::linked_ahead_count(), ahead + 16);
  EXPECT_EQ(gpu::warmed_count(), warmed + 15) << "the resolve and the mesh's programs were not warmed";
  EXPECT_EQ(gpu::programs_linking(), 0) << "a program linked ahead was not the one the frame used";
}

// The counted draw grows a triangle that reaches behind the eye by its edge
// lines in homogeneous coordinates (crossings.vert.glsl). Where the grown
// lines pass the projected corner opposite one of them, the corners' sign
// turns; drawn over the whole view there instead, as it once was, every such
// triangle shaded every pixel: stained_glass at 64×48 shaded 3.9 M fragments
// (1279 per pixel) against 0.48 M (156 per pixel) with the sign, and 0.52 M
// before the growth. The bound, 250 per pixel, leaves that 60 % of headroom.
TEST(LightVolume, TrianglesBehindTheEyeShadeOnlyNearTheirPart) {
  const FrameImages frame = kit::test::render(find_method("light_volume"), builtin_scene("stained_glass"), {}, 64, 48);
  const double fragments = stat(frame, "fragments");
  if (!(fragments > 0.0)) GTEST_SKIP() << "no GL_ARB_pipeline_statistics_query to count fragments";
  EXPECT_LT(fragments, 250.0 * 64 * 48);
}

// A grid finer than the map holds nothing more (a vertex per texel): it is
// clamped to the map, said once in a warning, not silently.
TEST(LightVolume, AGridFinerThanTheMapIsClampedWithAWarning) {
  const Scene scene = builtin_scene("teapot_spot");
  const CapturedWarnings warnings;
  auto method = prepared(find_method("light_volume"), scene, {"shadow_resolution=128", "volume_resolution=512"});
  const FrameImages first = airlight::render(*method, scene, 32, 24);
  const FrameImages second = airlight::render(*method, scene, 32, 24);
  EXPECT_EQ(warnings.text(), "airlight: warning: volume_resolution: 512 is above the shadow maps' 128: the grid is "
                            "128, a vertex per texel (what a map holds)\n");
  const auto triangles = [](const FrameImages& f) {
    for (const auto& [name, value] : f.stats)
      if (name == "volume_triangles") return value;
    return -1.0;
  };
  EXPECT_EQ(triangles(first), 6.0 * 128 * 128 + 12 * 128);  // one spot's map: 6R² + 12R (its rim) at R = 128
  EXPECT_EQ(triangles(second), triangles(first));
}

// biri_sphere seen from an eye moved to `position`, looking at `look_at`: the
// eye's count starts where the eye is, 0 inside the lit volume, 1 outside.
void expect_eye_case(const char* name, glm::vec3 position, glm::vec3 look_at) {
  Scene scene = builtin_scene("biri_sphere");
  scene.name = name;
  scene.camera.position = position;
  scene.camera.look_at = look_at;
  const double e = error_of(scene, {}, fine_reference_airlight(scene, width, height));
  std::printf("%s: rRMSE %.5f\n", name, e);
  EXPECT_LT(e, 0.02);  // the 256² grid's steps over the 1024² map at the sphere's shadow edges (measured below)
}

// In the spot's lit cone, between the light and the sphere's shadow, looking
// down through it (measured 0.0070).
TEST(LightVolume, CameraInsideTheLitVolume) {
  expect_eye_case("biri_sphere_eye_lit", {0.6f, 4.0f, 0.8f}, {0.0f, 1.0f, 0.0f});
}

// In the sphere's shadow, below it, looking past it at the cone (measured 0.012).
TEST(LightVolume, CameraInsideAShadow) {
  expect_eye_case("biri_sphere_eye_shadowed", {0.1f, 2.0f, 0.1f}, {1.5f, 0.5f, 0.0f});
}

}  // namespace
}  // namespace airlight::methods
