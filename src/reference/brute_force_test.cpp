#include "reference/brute_force.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <numbers>
#include <numeric>

#include "geometry/camera.hpp"
#include "optics/closed_form.hpp"
#include "optics/test_support.hpp"
#include "reference/reference.hpp"

namespace airlight::reference {
namespace {

using glm::dvec3;
using optics::testing::homogeneous_scene;
using optics::testing::point_light;
using optics::testing::relative_error;

optics::Ray ray_from(const dvec3& origin, const dvec3& toward) {
  return {origin, glm::normalize(toward - origin)};
}

// Where the scene's camera ends `ray` when nothing is in its way.
double far_of(const Scene& scene, const optics::Ray& ray) {
  return geometry::far_distance(scene.camera, ray.dir);
}

// ∫ over [a, b] of the unoccluded isotropic point light (Sun et al. 2005), as a
// difference of integrals from the eye.
double sun_between(const Scene& scene, const dvec3& light, double intensity, const optics::Ray& ray, double a,
                   double b) {
  const double s = scene.medium.sigma_s.x, t = scene.medium.sigma_t().x;
  return optics::sun_airlight(s, t, intensity, ray.origin, ray.dir, light, b) -
         optics::sun_airlight(s, t, intensity, ray.origin, ray.dir, light, a);
}

// ---- against closed forms ---------------------------------------------------

TEST(BruteForce, PointLightInFogMatchesSun) {
  Scene scene = homogeneous_scene(0.05f, 0.02f);
  const glm::vec3 light(0.7f, 2.3f, -1.1f);
  scene.lights = {point_light(light, 100.0f)};
  // Past the light, 1 mm from it, and far from it.
  for (const dvec3 toward : {dvec3(light), dvec3(light) + dvec3(0, 1e-3, 0), dvec3(-3, -1, -2)}) {
    const optics::Ray ray = ray_from(dvec3(scene.camera.position), toward + dvec3(0, 0, 1e-7));
    const dvec3 got = brute_force_airlight(scene, ray);
    const double expected = sun_between(scene, dvec3(light), 100.0, ray, 0.0, far_of(scene, ray));
    // 1e-6: both are double-precision quadratures to ~1e-10.
    EXPECT_LT(relative_error(got.x, expected), 1e-6) << got.x << " vs " << expected;
  }
}

TEST(BruteForce, SimplifiedModelMatchesNilsson) {
  Scene scene = homogeneous_scene(0.1f, 0.05f);  // σa is ignored: T = 1 (Nilsson eq. 2.15)
  scene.light_model = {LightModelType::simplified, 0.5f, 2.0f};
  const glm::vec3 light(-1.0f, 1.5f, 0.5f);
  scene.lights = {point_light(light, 40.0f)};
  const optics::Ray ray = ray_from(dvec3(scene.camera.position), dvec3(1, 0.5, -3));
  const double d = far_of(scene, ray);
  const double expected = optics::nilsson_airlight(0.1, 40.0, 0.5, 2.0, ray.origin, ray.dir, dvec3(light), 0.0, d);
  EXPECT_LT(relative_error(brute_force_airlight(scene, ray).x, expected), 1e-6);  // as above
}

// A casting half-plane y = 1, x <= 0 above the view ray y = 0 and the light at
// (0, 2, 0) above it: the line from the light to (x, y < 1, z) crosses y = 1 at
// x/(2 − y), so exactly x < 0 is in shadow, and the view ray along +x from
// x = −5 is lit from t = 5 on.
TEST(BruteForce, HalfPlaneShadowMatchesSunOverTheLitPart) {
  Scene scene = homogeneous_scene(0.05f, 0.02f);
  scene.lights = {point_light({0, 2, 0}, 100.0f)};
  Mesh wall;
  wall.positions = {{-20, 1, -20}, {0, 1, -20}, {0, 1, 20}, {-20, 1, 20}};
  wall.normals.assign(4, {0, 1, 0});
  wall.triangles = {{0, 1, 2}, {0, 2, 3}};
  scene.meshes = {wall};
  scene.camera.position = {-5, 0, 0};
  scene.camera.look_at = {0, 0, 0};
  const optics::Ray ray{dvec3(-5, 0, 0), dvec3(1, 0, 0)};
  const double expected = sun_between(scene, {0, 2, 0}, 100.0, ray, 5.0, far_of(scene, ray));
  EXPECT_LT(relative_error(brute_force_airlight(scene, ray).x, expected), 1e-6);  // as above
}

// A hard-edged spot at the origin pointing down with a 30° cone over the view
// ray y = −1 along +x: lit exactly where |x| <= tan 30°.
TEST(BruteForce, HardSpotConeMatchesSunInsideTheCone) {
  Scene scene = homogeneous_scene(0.05f, 0.02f);
  Light spot = point_light({0, 0, 0}, 100.0f);
  spot.type = LightType::spot;
  spot.direction = {0, -1, 0};
  spot.cone_deg = 30.0f;
  scene.lights = {spot};
  scene.camera.position = {-5, -1, 0};
  scene.camera.look_at = {0, -1, 0};
  const optics::Ray ray{dvec3(-5, -1, 0), dvec3(1, 0, 0)};
  const double half = std::tan(std::numbers::pi / 6.0);
  const double expected = sun_between(scene, {0, 0, 0}, 100.0, ray, 5.0 - half, 5.0 + half);
  EXPECT_LT(relative_error(brute_force_airlight(scene, ray).x, expected), 1e-6);  // as above
}

TEST(BruteForce, BeamMatchesItsClosedForm) {
  Scene scene = homogeneous_scene(0.1f, 0.05f);
  // Straight down from y = 3, 2 × 2 m, 5 m long; the view ray crosses it along x at y = 1.
  scene.lights = {optics::testing::beam_light({0, -1, 0}, {0, 0, 1}, Beam{{0, 3, 0}, {2, 2}, 5}, 7.0f)};
  scene.camera.position = {-4, 1, 0};
  scene.camera.look_at = {0, 1, 0};
  const optics::Ray ray{dvec3(-4, 1, 0), dvec3(1, 0, 0)};
  // Leg from the aperture s0 = 2 m, not changing along the ray (c = 0), inside for t in [3, 5].
  const double expected = optics::testing::beam_airlight(0.1, 0.15, 7.0, 2.0, 0.0, 3.0, 5.0);
  EXPECT_LT(relative_error(brute_force_airlight(scene, ray).x, expected), 1e-6);  // as above
}

// ---- the reference against brute force --------------------------------------

struct Worst {
  double error = 0.0;  // |reference − brute force| / (|brute force| + floor)
  glm::ivec2 pixel{0};
  double reference = 0.0, brute = 0.0;
};

// The relative error's floor: 1e-4 of the image's brightest pixel, so that
// pixels 1e4 times darker than the light shafts do not judge the reference.
constexpr double floor_fraction = 1e-4;
// The reference's rel_tol, 1e-3 of each light's integral: its |K15 − G7|
// estimates are conservative, Embree's float rays move shadow edges by ~1e-7
// of the coordinates and the image rounds to float (6e-8), all far below it
// (measured worst: 3e-4, docs/decisions.md "The reference checked by brute force").
constexpr double tolerance = 1e-3;

Worst compare(const Image& ref, const std::vector<glm::ivec2>& pixels, const std::vector<dvec3>& brute) {
  double brightest = 0.0;
  for (const glm::vec3& p : ref.pixels) brightest = std::max({brightest, double(p.x), double(p.y), double(p.z)});
  Worst worst;
  for (std::size_t k = 0; k < pixels.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      const double r = ref.at(pixels[k].x, pixels[k].y)[c], b = brute[k][c];
      const double e = std::abs(r - b) / (std::abs(b) + floor_fraction * brightest);
      if (e > worst.error) worst = {e, pixels[k], r, b};
    }
  return worst;
}

// A 4 × 4 grid, the 4 brightest pixels (light images, the shafts' cores) and
// the 4 with the largest jump to a neighbour (shadow and cone edges).
std::vector<glm::ivec2> probe_pixels(const Image& ref) {
  std::vector<glm::ivec2> pixels;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) pixels.push_back({(2 * i + 1) * ref.width / 8, (2 * j + 1) * ref.height / 8});
  std::vector<int> order(ref.width * ref.height);
  std::iota(order.begin(), order.end(), 0);
  auto value = [&](int i, int j) { return double(glm::length(ref.at(i, j))); };
  auto jump = [&](int k) {
    const int i = k % ref.width, j = k / ref.width;
    double most = 0.0;
    if (i + 1 < ref.width) most = std::max(most, std::abs(value(i + 1, j) - value(i, j)));
    if (j + 1 < ref.height) most = std::max(most, std::abs(value(i, j + 1) - value(i, j)));
    return most;
  };
  for (auto key : {std::function<double(int)>([&](int k) { return value(k % ref.width, k / ref.width); }),
                   std::function<double(int)>(jump)}) {
    std::partial_sort(order.begin(), order.begin() + 4, order.end(), [&](int a, int b) { return key(a) > key(b); });
    for (int n = 0; n < 4; ++n) pixels.push_back({order[n] % ref.width, order[n] / ref.width});
  }
  return pixels;
}

TEST(BruteForce, ReferenceMatchesOnEveryBuiltinScene) {
  constexpr int width = 32, height = 24;
  for (const std::string& name : builtin_scene_names()) {
    const Scene scene = builtin_scene(name);
    const Image ref = render(scene, width, height).airlight;
    const std::vector<glm::ivec2> pixels = probe_pixels(ref);
    const Worst worst = compare(ref, pixels, brute_force_airlight(scene, width, height, pixels));
    std::printf("%-18s worst %.2e at (%d, %d): %.6g vs %.6g\n", name.c_str(), worst.error, worst.pixel.x,
                worst.pixel.y, worst.reference, worst.brute);
    EXPECT_LT(worst.error, tolerance) << name;
  }
}

// Every pixel of a small image, on every built-in: the pixels between the
// probes above are where the reference lost lit slivers (whole-ray panels
// around a spot, unprobed panel ends, 32 first segments: toth_hall 45% off
// at 64×48).
TEST(BruteForceEveryPixel, ReferenceMatchesOnEveryBuiltinScene) {
  constexpr int width = 32, height = 24;
  std::vector<glm::ivec2> pixels;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) pixels.push_back({i, j});
  for (const std::string& name : builtin_scene_names()) {
    const Scene scene = builtin_scene(name);
    const Image ref = render(scene, width, height).airlight;
    const auto t0 = std::chrono::steady_clock::now();
    const Worst worst = compare(ref, pixels, brute_force_airlight(scene, width, height, pixels));
    std::printf("%-18s worst %.2e at (%d, %d): %.6g vs %.6g  [brute %.2f s]\n", name.c_str(), worst.error,
                worst.pixel.x, worst.pixel.y, worst.reference, worst.brute,
                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    EXPECT_LT(worst.error, tolerance) << name;
  }
}

}  // namespace
}  // namespace airlight::reference
