// shadow_planes (Biri 2006) against the CPU reference (docs/design.md §6): exact
// volumetric shadows whatever the order and nesting of the casters' volumes,
// with the eye inside them, for open casters, past the crossing pool's
// capacity, and never a NaN.
#include "core/metrics.hpp"
#include "geometry/shadow_edges.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <airlight/method.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <glm/geometric.hpp>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace airlight::methods {
namespace {

using namespace kit::test;

constexpr int width = 128, height = 96;

FrameImages shadow_planes(const Scene& scene, const std::vector<std::string>& settings = {}, int w = width,
                          int h = height) {
  return kit::test::render(find_method("shadow_planes"), scene, settings, w, h);
}

// Against the reference with 256 first segments (fine_reference_airlight).
// Exact up to Γ's accuracy and the reference's quadrature (rel_tol 1e-3): the
// quality table's bound, and a max-abs bound of 0.5% of the reference's peak
// (a pixel on a shadow edge: the reference's segments end at the edges it finds
// to rel_tol, Γ integrates to the exact crossing).
void expect_matches_reference(const Scene& scene, int w = width, int h = height,
                              const std::vector<std::string>& settings = {}) {
  const Image ref = fine_reference_airlight(scene, w, h);
  const ImageError e = compare_images(shadow_planes(scene, settings, w, h).airlight, ref);
  float peak = 0.0f;
  for (const glm::vec3& p : ref.pixels) peak = std::max({peak, p.r, p.g, p.b});
  std::printf("%s %d×%d: rRMSE %.5f, max abs %.5f (peak %.3f)\n", scene.name.c_str(), w, h, e.rel_rmse, e.max_abs,
              peak);
  EXPECT_LT(e.rel_rmse, 0.005) << scene.name;
  EXPECT_LT(e.max_abs, 0.005 * peak) << scene.name;
}

TEST(ShadowPlanes, RegisteredWithItsSettings) {
  std::set<std::string> names;
  for (const SettingSpec& s : find_method("shadow_planes").settings) names.insert(s.name);
  EXPECT_EQ(names, (std::set<std::string>{"shadow_resolution", "shadow_bias", "capacity", "samples", "max_edges", "scale", "upsample"}));
}

TEST(ShadowPlanes, MatchesTheReferenceAtASecondSize) {
  for (const char* name : {"biri_sphere", "biri_pens", "teapot_spot"}) expect_matches_reference(builtin_scene(name), 80, 60);
}

// The eye under the sphere of biri_sphere, inside its shadow volume, looking
// out through the shadow's side into the lit cone: the count starts at the
// eye's, not at 0 (Biri's "slightly different strategy").
TEST(ShadowPlanes, CameraInsideAShadowVolume) {
  Scene scene = builtin_scene("biri_sphere");
  scene.name = "biri_sphere_eye_in_shadow";
  scene.camera.position = {0.1f, 1.6f, 0.2f};
  scene.camera.look_at = {2.5f, 1.2f, -1.0f};
  expect_matches_reference(scene);
}

// The eye 0.1 m outside the sphere's shadow volume looking into it, with the
// near plane 0.5 m away: the planes between the eye and the near plane are
// drawn all the same (no near clipping), so the count is right from the eye.
TEST(ShadowPlanes, NearPlaneDoesNotCutThePlanes) {
  Scene scene = builtin_scene("biri_sphere");
  scene.name = "biri_sphere_near_plane";
  scene.camera.position = {1.0f, 2.0f, 0.0f};
  scene.camera.look_at = {-1.0f, 1.6f, 0.6f};
  scene.camera.near = 0.5f;
  expect_matches_reference(scene);
}

// Shadow in shadow (Biri §5.1.4, Fig. 4): a wide slab high under the spot, a
// box in its shadow, a sphere in both shadows and a bar crossing them, so that
// many view rays enter and leave several volumes, nested and overlapping.
Scene nested_casters() {
  Scene s = builtin_scene("biri_sphere");
  s.name = "nested_casters";
  s.meshes.resize(1);  // the floor
  s.meshes.push_back(box({-1.2f, 3.6f, -0.6f}, {0.4f, 3.7f, 0.6f}, Color(0.7f)));
  s.meshes.push_back(box({-0.5f, 2.4f, -0.4f}, {0.1f, 2.9f, 0.3f}, Color(0.7f)));
  s.meshes.push_back(box({-0.2f, 1.0f, -0.2f}, {0.6f, 1.6f, 0.4f}, Color(0.7f)));
  s.meshes.push_back(box({-1.5f, 3.0f, 0.1f}, {1.5f, 3.15f, 0.3f}, Color(0.7f)));
  return s;
}

TEST(ShadowPlanes, ShadowInShadowMatchesTheReference) { expect_matches_reference(nested_casters()); }

// The casters in the opposite order: the same lit intervals, so the same image
// up to the order of floating-point sums at equal t (none here): bit for bit
// or within 1e-6 of the peak.
TEST(ShadowPlanes, CasterOrderDoesNotMatter) {
  const Scene scene = nested_casters();
  Scene reversed = scene;
  std::reverse(reversed.meshes.begin() + 1, reversed.meshes.end());
  const Image a = shadow_planes(scene).airlight, b = shadow_planes(reversed).airlight;
  float peak = 0.0f;
  for (const glm::vec3& p : a.pixels) peak = std::max({peak, p.r, p.g, p.b});
  EXPECT_LE(compare_images(b, a).max_abs, 1e-6 * peak);
}

// An open caster (a half-open box: no top) and a lone quad: not closed
// 2-manifolds, so every edge of their triangles bounds its own volume; the
// shadows stay exact, and the report says which casters took that path.
Scene open_casters() {
  Scene s = builtin_scene("biri_sphere");
  s.name = "open_casters";
  s.meshes.resize(1);
  Mesh cup = box({-0.8f, 2.6f, -0.3f}, {-0.2f, 3.2f, 0.3f}, Color(0.7f));
  cup.triangles.erase(cup.triangles.begin() + 6, cup.triangles.begin() + 8);  // the +y face
  s.meshes.push_back(cup);
  Mesh quad;
  quad.name = "quad";
  quad.positions = {{0.2f, 3.0f, -0.4f}, {0.9f, 3.1f, -0.4f}, {0.9f, 3.1f, 0.4f}, {0.2f, 3.0f, 0.4f}};
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  s.meshes.push_back(quad);
  return s;
}

TEST(ShadowPlanes, OpenCastersShadowExactly) {
  const Scene scene = open_casters();
  expect_matches_reference(scene);
  const FrameImages frame = shadow_planes(scene);
  EXPECT_EQ(stat(frame, "caster0_silhouettes"), 1.0);  // the floor slab is closed
  EXPECT_EQ(stat(frame, "caster1_triangle_volumes"), 1.0);
  EXPECT_EQ(stat(frame, "caster2_triangle_volumes"), 1.0);
}

// Every built-in caster is closed once welded, so its planes are its
// silhouette edges (the method's report for teapot_spot, and the topology the
// method builds for every other built-in: rendering each would compile a
// program per scene for nothing).
TEST(ShadowPlanes, EveryBuiltinCasterUsesItsSilhouettes) {
  const Scene teapot = builtin_scene("teapot_spot");
  const FrameImages frame = shadow_planes(teapot, {}, 16, 12);
  for (size_t m = 0; m < teapot.meshes.size(); ++m)
    EXPECT_EQ(stat(frame, "caster" + std::to_string(m) + "_silhouettes"), 1.0) << teapot.meshes[m].name;
  for (const std::string& name : builtin_scene_names())
    for (const Mesh& mesh : builtin_scene(name).meshes)
      EXPECT_TRUE(geometry::build_topology(mesh.positions, mesh.triangles).closed) << name << " " << mesh.name;
}

// A pool for 0.1 crossings per pixel: biri_pens has ~0.9 on average and pixels
// with four or more, so the pass grows the pool and draws again, and the
// image is the one a large pool gives.
TEST(ShadowPlanes, MoreCrossingsThanThePoolHoldsAreNotDropped) {
  const Scene scene = builtin_scene("biri_pens");
  const FrameImages small = shadow_planes(scene, {"capacity=0.1"}), large = shadow_planes(scene, {"capacity=64"});
  EXPECT_GE(stat(small, "redraws"), 1.0);
  EXPECT_EQ(stat(large, "redraws"), 0.0);
  EXPECT_GT(stat(small, "crossings"), 0.1 * width * height);
  EXPECT_EQ(stat(small, "crossings"), stat(large, "crossings"));
  // Every crossing is a fragment; fragments beyond the surface or behind the eye add none.
  EXPECT_GE(stat(large, "fragments"), stat(large, "crossings"));
  EXPECT_TRUE(small.airlight.pixels == large.airlight.pixels);
}

// The airlight needs no shadow map: a frame without the surface term draws
// none. Its passes: the G-buffer, the silhouettes' CPU build, the crossings
// and the resolve.
TEST(ShadowPlanes, AirlightPassDrawsNoShadowMap) {
  const Scene scene = builtin_scene("biri_sphere");
  auto method = prepared(find_method("shadow_planes"), scene, {});
  std::vector<std::string> passes;
  for (const auto& t : airlight::render(*method, scene, 32, 24, false).times) passes.push_back(t.pass);
  EXPECT_EQ(passes, (std::vector<std::string>{"gbuffer", "build", "crossings", "airlight"}));
}

// A caster with casts_shadows = false lets the light through: biri_sphere's
// sphere marked so casts no shadow into the beam in the reference (its
// occlusion rays skip it), in raymarch (the shadow maps skip it) and here (no
// planes), while it still ends the view rays that hit it.
TEST(ShadowPlanes, ACasterThatCastsNoShadowLetsTheLightThrough) {
  Scene scene = builtin_scene("biri_sphere");
  scene.name = "biri_sphere_no_shadow";
  scene.meshes[1].casts_shadows = false;
  expect_matches_reference(scene);
  EXPECT_EQ(stat(shadow_planes(scene), "caster1_silhouettes"), -1.0);  // not a caster at all
  const Image ref = fine_reference_airlight(scene, width, height);
  const Image marched = kit::test::render(find_method("raymarch"), scene, {"steps=64"}, width, height).airlight;
  EXPECT_LT(compare_images(marched, ref).rel_rmse, 0.01);  // raymarch's own error at N = 64, equiangular
  const Image shadowed = fine_reference_airlight(builtin_scene("biri_sphere"), width, height);
  EXPECT_GT(compare_images(shadowed, ref).rel_rmse, 0.05);  // the sphere's shadow is a large part of the beam
}

// Configurations that put 0/0 or ∞ within reach: the light inside a caster's
// bounding box or on its surface, the camera on a shadow plane or at the
// light, casters crossing the near plane. Every pixel finite and non-negative.
TEST(ShadowPlanes, NoNaNOrInfInHardConfigurations) {
  std::mt19937 random(2006);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const Scene base = nested_casters();
  for (int k = 0; k < 24; ++k) {
    Scene s = base;
    const glm::vec3 corner = s.meshes[1 + k % 4].positions[0];
    s.lights[0].position = k % 3 == 0 ? corner : glm::vec3(0.6f * u(random), 2.5f + 1.5f * u(random), 0.6f * u(random));
    s.lights[0].type = k % 5 == 0 ? LightType::point : (k % 5 == 1 ? LightType::directional : LightType::spot);
    s.lights[0].irradiance = Color(2.0f);
    s.camera.position = k % 4 == 0 ? s.lights[0].position + glm::vec3(0.0f, 0.0f, 0.01f)
                                   : glm::vec3(2.0f * u(random), 1.5f + 1.5f * u(random), 3.0f * u(random));
    if (k % 6 == 0) s.camera.position = s.meshes[2].positions[1];  // on a shadow plane's edge
    s.camera.look_at = glm::vec3(0.0f, 2.0f, 0.0f);
    const FrameImages frame = shadow_planes(s, {}, 24, 18);
    EXPECT_TRUE(all_finite_and_non_negative(frame.airlight)) << k;
  }
}

}  // namespace
}  // namespace airlight::methods
