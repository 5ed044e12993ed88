// A directional light's beam through the GPU frame end to end: the airlight of
// `raymarch` (scene.glsl light_map, light_leg_depth and the shadow map fitted
// to the beam) against the reference on a small scene. The methods sit above
// the gpu layer; only this test links them.
#include "core/metrics.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <memory>
#include <string>
#include <vector>

namespace airlight {
namespace {

constexpr int width = 128, height = 96;

Mesh quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, Color albedo) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.positions = {a, b, c, d};
  mesh.normals.assign(4, glm::normalize(glm::cross(b - a, c - a)));
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.albedo = albedo;
  return mesh;
}

// A beam with a coloured gobo falls from above onto a floor in front of a back
// wall (so that every view ray ends on a surface, a few metres away), and a
// slab hanging inside the beam casts a shadow shaft through it.
Scene beam_scene() {
  Scene s;
  s.name = "beam";
  s.camera.position = {0.0f, 2.0f, 6.0f};
  s.camera.look_at = {0.0f, 1.5f, 0.0f};
  s.camera.far = 20.0f;
  s.medium.sigma_s = Color(0.08f);
  s.medium.sigma_a = Color(0.02f);
  s.medium.phase.lobes = {PhaseLobe{PhaseType::henyey_greenstein, 0.2f, 1.0f}};
  s.meshes.push_back(quad({-5, 0, 5}, {5, 0, 5}, {5, 0, -3}, {-5, 0, -3}, Color(0.5f)));   // floor
  s.meshes.push_back(quad({-5, 0, -3}, {5, 0, -3}, {5, 5, -3}, {-5, 5, -3}, Color(0.5f)));  // back wall
  s.meshes.push_back(quad({-0.4f, 2.8f, 0.2f}, {0.4f, 2.8f, 0.2f}, {0.4f, 2.8f, -0.6f}, {-0.4f, 2.8f, -0.6f},
                          Color(0.5f)));  // the slab, facing up
  auto gobo = std::make_shared<Image>(8, 6);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x)
      gobo->at(x, y) = Color(0.2f + 0.8f * x / 7.0f, 0.2f + 0.8f * y / 5.0f, (x + y) % 2 ? 1.0f : 0.4f);
  Light beam;
  beam.type = LightType::directional;
  beam.direction = glm::normalize(glm::vec3(0.2f, -1.0f, -0.1f));
  beam.irradiance = Color(4.0f);
  beam.gobo_up = {0, 0, -1};
  beam.gobo = gobo;
  beam.beam = Beam{{0.0f, 4.0f, -0.5f}, {3.0f, 2.0f}, 6.0f};
  s.lights.push_back(beam);
  return s;
}

FrameImages render(const std::string& method_name, const Scene& scene, const std::vector<std::string>& assignments) {
  return kit::test::render(find_method(method_name), scene, assignments, width, height);
}

// Uniform steps (~3 cm here) straddle the beam's faces, where the integrand
// jumps: the midpoint rule's error there is O(step) per crossing, so the
// rRMSE falls as 1/N, down to the slab's shadow edges through the 1024² map.
// Bound at N = 256: 0.03; and N = 1024 must at least halve it (the error is
// the sampling's, not a bias).
TEST(BeamAirlight, RaymarchMatchesTheReference) {
  const Scene scene = beam_scene();
  const Image reference = render("reference", scene, {}).airlight;
  const Image march = render("raymarch", scene, {"steps=256", "sampling=uniform"}).airlight;
  const ImageError e = compare_images(march, reference);
  const Image finer_march = render("raymarch", scene, {"steps=1024", "sampling=uniform"}).airlight;
  const ImageError finer = compare_images(finer_march, reference);
  int dark = 0, lit = 0;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(march.pixels[i][c])) << "pixel " << i;
    // A view ray that misses the beam sees nothing, on both sides.
    if (reference.pixels[i] == glm::vec3(0.0f)) {
      ++dark;
      EXPECT_EQ(march.pixels[i], glm::vec3(0.0f)) << "pixel " << i;
    } else {
      ++lit;
    }
  }
  std::printf("raymarch on a beam: rRMSE %.4f (N = 1024: %.4f), max abs %.4g (mean %.4g); %d pixels miss the "
              "beam, %d see it\n", e.rel_rmse, finer.rel_rmse, e.max_abs, e.mean_reference, dark, lit);
  EXPECT_GT(dark, width * height / 10);
  EXPECT_GT(lit, width * height / 4);
  EXPECT_LT(e.rel_rmse, 0.03) << "uniform steps across the beam's faces (measured 0.020)";
  EXPECT_LT(finer.rel_rmse, 0.5 * e.rel_rmse) << "the error must fall with N";
}

}  // namespace
}  // namespace airlight
