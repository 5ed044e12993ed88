#include "reference/reference.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <memory>
#include <numbers>

#include "geometry/camera.hpp"
#include "optics/airlight.hpp"
#include "optics/closed_form.hpp"
#include "optics/light.hpp"
#include "optics/test_support.hpp"

namespace airlight::reference {
namespace {

using glm::dvec3;
using std::numbers::pi;

// ---- scenes built in code -------------------------------------------------

Mesh quad_y(double y, double half_size, Color albedo) {
  Mesh mesh;
  mesh.name = "floor";
  const auto h = static_cast<float>(half_size);
  const auto fy = static_cast<float>(y);
  mesh.positions = {{-h, fy, -h}, {h, fy, -h}, {h, fy, h}, {-h, fy, h}};
  mesh.normals.assign(4, {0, 1, 0});
  mesh.triangles = {{0, 2, 1}, {0, 3, 2}};
  mesh.albedo = albedo;
  return mesh;
}

// A UV sphere; its facets lie between the inscribed radius r·cos(π/rings)·cos(π/segments)
// and r.
constexpr int sphere_rings = 24, sphere_segments = 48;

Mesh sphere(glm::vec3 centre, float radius) {
  Mesh mesh;
  mesh.name = "sphere";
  for (int i = 0; i <= sphere_rings; ++i)
    for (int k = 0; k <= sphere_segments; ++k) {
      const double theta = pi * i / sphere_rings, phi = 2 * pi * k / sphere_segments;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      mesh.positions.push_back(centre + radius * n);
      mesh.normals.push_back(n);
    }
  const auto index = [](int i, int k) { return static_cast<unsigned>(i * (sphere_segments + 1) + k); };
  for (int i = 0; i < sphere_rings; ++i)
    for (int k = 0; k < sphere_segments; ++k) {
      mesh.triangles.push_back({index(i, k), index(i + 1, k), index(i + 1, k + 1)});
      mesh.triangles.push_back({index(i, k), index(i + 1, k + 1), index(i, k + 1)});
    }
  return mesh;
}

double inscribed_radius(double radius) {
  return radius * std::cos(pi / sphere_rings) * std::cos(pi / sphere_segments);
}

// A closed axis-aligned box: 6 faces sharing their corner positions exactly.
Mesh box(glm::vec3 lo, glm::vec3 hi) {
  Mesh mesh;
  mesh.name = "box";
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      glm::vec3 n(0.0f);
      n[axis] = side ? 1.0f : -1.0f;
      const auto base = static_cast<unsigned>(mesh.positions.size());
      for (int corner = 0; corner < 4; ++corner) {
        glm::vec3 p;
        p[axis] = side ? hi[axis] : lo[axis];
        p[u] = (corner == 1 || corner == 2) ? hi[u] : lo[u];
        p[v] = (corner >= 2) ? hi[v] : lo[v];
        mesh.positions.push_back(p);
        mesh.normals.push_back(n);
      }
      mesh.triangles.push_back({base, base + 1, base + 2});
      mesh.triangles.push_back({base, base + 2, base + 3});
    }
  return mesh;
}

Light point_light(glm::vec3 position, Color intensity) {
  Light light;
  light.type = LightType::point;
  light.position = position;
  light.intensity = intensity;
  return light;
}

Light spot_light(glm::vec3 position, glm::vec3 target, Color intensity, float cone_deg) {
  Light light = point_light(position, intensity);
  light.type = LightType::spot;
  light.direction = glm::normalize(target - position);
  light.cone_deg = cone_deg;
  return light;
}

Camera camera(glm::vec3 position, glm::vec3 look_at, float far = 20.0f) {
  Camera c;
  c.position = position;
  c.look_at = look_at;
  c.fov_y_deg = 50.0f;
  c.near = 0.1f;
  c.far = far;
  return c;
}

// Fog and lights only, seen from outside: the common start of the tests.
Scene fog_scene(Color sigma_s, Color sigma_a) {
  Scene scene;
  scene.name = "test";
  scene.camera = camera({0, 1, 6}, {0, 1, 0});
  scene.medium.sigma_s = sigma_s;
  scene.medium.sigma_a = sigma_a;
  return scene;
}

// ---- image checks ----------------------------------------------------------

optics::Ray pixel_ray(const Scene& scene, const Image& image, int i, int j) {
  return geometry::primary_ray(scene.camera, image.width, image.height, i + 0.5, j + 0.5);
}

// docs/design.md §6: sqrt(mean((m − r)²)) / mean(r) over all pixels and channels.
double relative_rmse(const Image& m, const Image& r) {
  double squares = 0.0, sum = 0.0;
  for (size_t k = 0; k < r.pixels.size(); ++k)
    for (int c = 0; c < 3; ++c) {
      const double e = static_cast<double>(m.pixels[k][c]) - r.pixels[k][c];
      squares += e * e;
      sum += r.pixels[k][c];
    }
  const double n = 3.0 * static_cast<double>(r.pixels.size());
  return std::sqrt(squares / n) / (sum / n);
}

double total(const Image& image) {
  double sum = 0.0;
  for (const glm::vec3& p : image.pixels) sum += p.x + p.y + p.z;
  return sum;
}

void expect_finite_and_non_negative(const Images& frame, const std::string& what) {
  for (const Image* image : {&frame.airlight, &frame.surface, &frame.composite})
    for (const glm::vec3& p : image->pixels)
      for (int c = 0; c < 3; ++c) {
        ASSERT_TRUE(std::isfinite(p[c])) << what;
        ASSERT_GE(p[c], 0.0f) << what;
      }
}

// ---- (a) unoccluded point light against Sun et al.'s closed form ------------

TEST(Reference, UnoccludedPointLightMatchesSunAirlight) {
  Scene scene = fog_scene(Color(0.05f), Color(0.02f));
  const glm::vec3 light(0.7f, 2.3f, -1.1f);
  scene.lights = {point_light(light, Color(100.0f))};
  const Images frame = render(scene, 64, 48);  // default settings, as `airlight render` uses
  EXPECT_EQ(frame.nonfinite, 0);
  EXPECT_GT(frame.shadow_rays, 0);
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < 64; ++i) {
      const optics::Ray ray = pixel_ray(scene, frame.airlight, i, j);
      const double d = geometry::far_distance(scene.camera, ray.dir);
      const double expected = optics::sun_airlight(0.05, 0.07, 100.0, ray.origin, ray.dir, dvec3(light), d);
      // 0.1%: the default rel_tol promises 1e-3 of the integral (it does far
      // better here, since optics grades its panels around the closest approach).
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(frame.airlight.at(i, j)[c], expected, 1e-3 * expected) << i << "," << j;
    }
}

// ---- (b) hard-edged spot light against a brute-force midpoint sum -----------

struct BruteForce {
  dvec3 sum{0.0};
  dvec3 max_integrand{0.0};
  double step = 0.0;
};

// Σ e(x_k)·h over N midpoints on [0, d]: no splitting at the cone, no adaptivity.
BruteForce midpoint_sum(const Scene& scene, const optics::Ray& ray, double d, int n) {
  BruteForce b;
  b.step = d / n;
  for (int k = 0; k < n; ++k) {
    const dvec3 e = optics::inscatter(scene, scene.lights[0], ray, (k + 0.5) * b.step);
    b.sum += e * b.step;
    b.max_integrand = glm::max(b.max_integrand, e);
  }
  return b;
}

TEST(Reference, HardEdgedSpotLightMatchesBruteForceMidpointSum) {
  Scene scene = fog_scene({0.04f, 0.05f, 0.06f}, Color(0.01f));
  scene.lights = {spot_light({-4, 6, 2}, {0.5f, 0, -1}, {80, 100, 120}, 20.0f)};  // off screen: a smooth 1/r²
  constexpr int width = 32, height = 24, steps = 20000;
  const Images frame = render(scene, width, height, {.rel_tol = 1e-4});
  EXPECT_EQ(frame.nonfinite, 0);
  Image brute(width, height);
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const optics::Ray ray = pixel_ray(scene, brute, i, j);
      const BruteForce b = midpoint_sum(scene, ray, geometry::far_distance(scene.camera, ray.dir), steps);
      brute.at(i, j) = glm::vec3(b.sum);
      for (int c = 0; c < 3; ++c) {
        // The midpoint rule is off by at most h·max e at each of the (≤ 2) cone
        // crossings and by O(h²) elsewhere; 0.2% covers the rest (rel_tol, h²).
        const double bound = 2.0 * b.step * b.max_integrand[c] + 2e-3 * b.sum[c];
        ASSERT_NEAR(frame.airlight.at(i, j)[c], b.sum[c], bound) << i << "," << j << " channel " << c;
      }
    }
  // Over the image the edge errors average out: 0.1% relative RMSE (docs/design.md §6 measure).
  EXPECT_LT(relative_rmse(frame.airlight, brute), 1e-3);
  EXPECT_GT(total(frame.airlight), 0.0);
}

// ---- (c) a sphere's shadow in the fog: the reference is converged -----------

Scene shadowed_shaft() {
  Scene scene = fog_scene(Color(0.05f), Color(0.01f));
  scene.lights = {spot_light({0.5f, 5, -1}, {0, 0, -1}, Color(150.0f), 30.0f)};
  scene.meshes = {sphere({0.3f, 2.5f, -1}, 0.6f), quad_y(0.0, 10.0, Color(0.5f))};
  return scene;
}

TEST(Reference, SphereShadowAirlightIsConvergedInRelTol) {
  const Scene scene = shadowed_shaft();
  const Images coarse = render(scene, 64, 48);
  const Images fine = render(scene, 64, 48, {.rel_tol = 0.5e-3});
  EXPECT_EQ(coarse.nonfinite + fine.nonfinite, 0);
  // Halving rel_tol moves the image by less than 0.1% (the brief's convergence bar).
  EXPECT_LT(relative_rmse(coarse.airlight, fine.airlight), 1e-3);
  // And the shadow is really there: without the sphere the fog is brighter.
  Scene unshadowed = scene;
  unshadowed.meshes.erase(unshadowed.meshes.begin());
  EXPECT_LT(total(fine.airlight), 0.97 * total(render(unshadowed, 64, 48).airlight));
}

// ---- (d) surfaces: Lambertian plane, extinction on both legs, shadows --------

struct PlaneScene {
  Scene scene;
  glm::vec3 light{0.5f, 2.0f, -0.3f};
  Color intensity{10, 20, 30};
  Color albedo{0.5f, 0.6f, 0.7f};
};

// Looking down at a floor that fills the view.
PlaneScene plane_scene() {
  PlaneScene p;
  p.scene.camera = camera({0, 3, 3}, {0, 0, 0});
  p.scene.ambient = Color(0.02f);
  p.scene.lights = {point_light(p.light, p.intensity)};
  p.scene.meshes = {quad_y(0.0, 20.0, p.albedo)};
  return p;
}

struct FloorPoint {
  dvec3 position;
  double eye_distance;
};

FloorPoint floor_point(const optics::Ray& ray) {
  const double t = -ray.origin.y / ray.dir.y;
  return {ray.origin + t * ray.dir, t};
}

// albedo·ambient + albedo/π·I·cos θ/r² · exp(−σt·(r + t)), docs/design.md §1.
dvec3 lambert(const PlaneScene& p, const FloorPoint& f, double sigma_t, bool lit) {
  const dvec3 to_light = dvec3(p.light) - f.position;
  const double r = glm::length(to_light);
  const double direct = lit ? (to_light.y / r) / (r * r) * std::exp(-sigma_t * r) / pi : 0.0;
  return dvec3(p.albedo) * (dvec3(p.scene.ambient) + dvec3(p.intensity) * direct) *
         std::exp(-sigma_t * f.eye_distance);
}

void expect_lambertian_floor(const PlaneScene& p, double sigma_t, const Settings& settings = {}) {
  const Images frame = render(p.scene, 64, 48, settings);
  EXPECT_EQ(frame.nonfinite, 0);
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < 64; ++i) {
      const dvec3 expected = lambert(p, floor_point(pixel_ray(p.scene, frame.surface, i, j)), sigma_t, true);
      // Embree's float hit distance (~1e-6 relative) and float pixels: 1e-4.
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(frame.surface.at(i, j)[c], expected[c], 1e-4 * expected[c]) << i << "," << j;
    }
}

TEST(Reference, SurfaceOfPlaneUnderPointLightIsLambertian) {
  const PlaneScene p = plane_scene();
  expect_lambertian_floor(p, 0.0);
  const Images frame = render(p.scene, 16, 12);
  EXPECT_EQ(total(frame.airlight), 0.0);  // no medium, no airlight
}

TEST(Reference, SurfaceIsAttenuatedOnBothLegs) {
  PlaneScene p = plane_scene();
  p.scene.medium.sigma_a = Color(0.1f);  // absorbing only: T on both legs, no airlight
  expect_lambertian_floor(p, 0.1);
}

// Distance from `c` to the segment a → b.
double segment_distance(const dvec3& a, const dvec3& b, const dvec3& c) {
  const dvec3 ab = b - a;
  const double s = std::clamp(glm::dot(c - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(a + s * ab - c);
}

TEST(Reference, SphereShadowOnPlaneLeavesAmbientOnlyAndNoSelfShadowing) {
  PlaneScene p = plane_scene();
  p.light = {0.2f, 4.0f, 0.1f};
  p.scene.lights = {point_light(p.light, p.intensity)};
  const dvec3 centre(0.0, 2.0, 0.0);
  constexpr double radius = 0.5;
  p.scene.meshes.push_back(sphere(glm::vec3(centre), static_cast<float>(radius)));
  const Images frame = render(p.scene, 64, 48);
  int shadowed = 0, lit = 0;
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < 64; ++i) {
      const optics::Ray ray = pixel_ray(p.scene, frame.surface, i, j);
      if (segment_distance(ray.origin, floor_point(ray).position, centre) < radius * 1.01) continue;  // sees the sphere
      const FloorPoint f = floor_point(ray);
      const double miss = segment_distance(f.position, dvec3(p.light), centre);
      // Facets lie between the inscribed and the true radius: classify only clear cases.
      if (miss > inscribed_radius(radius) * 0.99 && miss < radius * 1.01) continue;
      const bool in_light = miss >= radius * 1.01;
      (in_light ? lit : shadowed)++;
      const dvec3 expected = lambert(p, f, 0.0, in_light);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(frame.surface.at(i, j)[c], expected[c], 1e-4 * expected[c]) << i << "," << j;
    }
  EXPECT_GT(shadowed, 20);
  EXPECT_GT(lit, 1000);
}

// A screen across the whole view at view depth `depth` (the camera's near plane: 0.1).
PlaneScene screen_scene(float depth) {
  PlaneScene p = plane_scene();
  Mesh screen = quad_y(0.0, 1.0, Color(1.0f));
  const glm::vec3 c(0, 3, 3), forward = glm::normalize(glm::vec3(0, -1, -1));
  const glm::vec3 right(1, 0, 0), up = glm::cross(right, forward);
  const glm::vec3 middle = c + depth * forward;
  screen.positions = {middle - right - up, middle + right - up, middle + right + up, middle - right + up};
  p.scene.meshes.push_back(screen);
  return p;
}

TEST(Reference, GeometryNearerThanTheNearPlaneIsClipped) { expect_lambertian_floor(screen_scene(0.05f), 0.0); }

// near_shift moves the near plane along each ray (0.1/cos θ off the axis, up
// to 0.127 at the corners here): a screen at view depth 0.12 is clipped once
// it moves 0.05 farther, and one at 0.05 is seen once it moves 0.08 nearer.
TEST(Reference, NearShiftMovesTheNearPlane) {
  expect_lambertian_floor(screen_scene(0.12f), 0.0, {.near_shift = 0.05});
  const Images clipped = render(screen_scene(0.05f).scene, 16, 12);
  const Images seen = render(screen_scene(0.05f).scene, 16, 12, {.near_shift = -0.08});
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 16; ++i) EXPECT_NE(seen.surface.at(i, j), clipped.surface.at(i, j)) << i << "," << j;
}

TEST(Reference, GeometryBeyondTheFarPlaneIsNotSeen) {
  PlaneScene p = plane_scene();
  p.scene.camera.far = 2.0f;  // the floor is 3·√2 ≈ 4.2 away along the axis
  const Images frame = render(p.scene, 16, 12);
  EXPECT_EQ(total(frame.surface), 0.0);
}

// ---- (e) a directional light's beam --------------------------------------------

// A vertical beam (right = −x, up = +z), aperture centred at (0, y, 0).
Light vertical_beam(float y, glm::vec2 size, float length, float irradiance) {
  return optics::testing::beam_light({0, -1, 0}, {0, 0, 1}, Beam{{0, y, 0}, size, length}, irradiance);
}

// The camera inside a wide beam (aperture 9 m above it, 100 m across, 30 m
// long): every view ray starts inside and leaves through the aperture, through
// the end, or not before the far plane; s(t) = 9 − dir.y·t. The closed form
// of optics/test_support.hpp per pixel.
TEST(Reference, UnoccludedBeamMatchesItsClosedFormOnEveryPixel) {
  Scene scene = fog_scene(Color(0.05f), Color(0.02f));
  scene.lights = {vertical_beam(10.0f, {100, 100}, 30.0f, 2.0f)};
  const Images frame = render(scene, 64, 48);  // default settings, as `airlight render` uses
  EXPECT_EQ(frame.nonfinite, 0);
  const double sigma_s = scene.medium.sigma_s.x, sigma_t = scene.medium.sigma_t().x;
  double worst = 0.0;
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < 64; ++i) {
      const optics::Ray ray = pixel_ray(scene, frame.airlight, i, j);
      const double s0 = 10.0 - ray.origin.y, c = -ray.dir.y;
      const double exit = c < 0.0 ? s0 / -c : (30.0 - s0) / c;  // the aperture or the end
      const double b = std::min(geometry::far_distance(scene.camera, ray.dir), exit);
      const double expected = optics::testing::beam_airlight(sigma_s, sigma_t, 2.0, s0, c, 0.0, b);
      worst = std::max(worst, std::abs(frame.airlight.at(i, j).x - expected) / expected);
      // 1e-6: float pixels (6e-8); the integrand is a smooth exponential on the
      // beam's part of the ray, which the quadrature gets to rounding.
      for (int k = 0; k < 3; ++k)
        ASSERT_NEAR(frame.airlight.at(i, j)[k], expected, 1e-6 * expected) << i << "," << j;
    }
  std::printf("camera inside a beam: worst relative error %.2e\n", worst);
}

// A narrow beam crossing the view: the centre pixel of an odd image looks
// along −z exactly, through the beam between z = 0.5 and −0.5 at s = 3; the
// image's side columns miss the beam and must be exactly dark.
TEST(Reference, BeamCrossingTheViewMatchesItsClosedForm) {
  Scene scene = fog_scene(Color(0.05f), Color(0.02f));
  scene.lights = {vertical_beam(4.0f, {2, 1}, 5.0f, 2.0f)};
  const Images frame = render(scene, 65, 49);
  const optics::Ray centre = pixel_ray(scene, frame.airlight, 32, 24);
  ASSERT_EQ(centre.dir, dvec3(0, 0, -1));
  const double expected = optics::testing::beam_airlight(scene.medium.sigma_s.x, scene.medium.sigma_t().x, 2.0,
                                                         3.0, 0.0, 5.5, 6.5);
  // 1e-6: float pixels, as above.
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(frame.airlight.at(32, 24)[k], expected, 1e-6 * expected);
  for (int j = 0; j < 49; ++j)
    for (int i : {0, 64}) EXPECT_EQ(frame.airlight.at(i, j), glm::vec3(0.0f)) << i << "," << j;
}

// A floor under a beam with a gobo: inside the beam's footprint the floor
// receives E·gobo(uv)·exp(−σt·4) (vertical light, cos θ_i = 1, 4 m below the
// aperture); outside it only ambient light.
TEST(Reference, FloorUnderABeamShowsItsGobo) {
  PlaneScene p = plane_scene();
  p.scene.medium.sigma_a = Color(0.1f);  // absorbing: the light's leg starts at the aperture
  Light beam = vertical_beam(4.0f, {3, 2}, 10.0f, 5.0f);
  auto gobo = std::make_shared<Image>(3, 2);
  for (int k = 0; k < 6; ++k) gobo->pixels[k] = Color(0.1f + 0.15f * k, 1.0f - 0.1f * k, (k % 2) ? 1.0f : 0.3f);
  beam.gobo = gobo;
  p.scene.lights = {beam};
  const Images frame = render(p.scene, 64, 48);
  int inside = 0, outside = 0;
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < 64; ++i) {
      const FloorPoint f = floor_point(pixel_ray(p.scene, frame.surface, i, j));
      const glm::dvec2 uv(0.5 - f.position.x / 3.0, 0.5 + f.position.z / 2.0);  // right = −x, up = +z
      // Embree's float hit point (~1e-6 m): leave out pixels that close to the footprint's edge.
      const double edge = std::min({uv.x, 1.0 - uv.x, uv.y, 1.0 - uv.y});
      if (std::abs(edge) < 1e-4) continue;
      const bool lit = edge > 0.0;
      (lit ? inside : outside)++;
      const dvec3 e = lit ? 5.0 * optics::sample_gobo(*gobo, uv) * std::exp(-0.1 * 4.0) : dvec3(0.0);
      const dvec3 expected = dvec3(p.albedo) * (dvec3(p.scene.ambient) + e / pi) * std::exp(-0.1 * f.eye_distance);
      // Embree's float hit distance and point (~1e-6 relative) and float pixels: 1e-4.
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(frame.surface.at(i, j)[c], expected[c], 1e-4 * expected[c]) << i << "," << j;
    }
  EXPECT_GT(inside, 300);
  EXPECT_GT(outside, 300);
}

// Occluders toward the light cast shadows wherever they are, upstream of the
// aperture too (docs/decisions.md): the beam bounds where light exists, and
// the GPU's shadow maps see every occluder.
TEST(Reference, OccluderUpstreamOfTheApertureShadowsTheBeam) {
  PlaneScene p = plane_scene();
  p.scene.lights = {vertical_beam(2.0f, {3, 2}, 10.0f, 5.0f)};
  p.scene.meshes.push_back(box({-0.3f, 3.0f, -0.3f}, {0.3f, 3.5f, 0.3f}));  // above the aperture
  const Images frame = render(p.scene, 64, 48);
  const optics::Ray ray = pixel_ray(p.scene, frame.surface, 32, 24);  // at the floor's centre
  const FloorPoint f = floor_point(ray);
  ASSERT_LT(std::max(std::abs(f.position.x), std::abs(f.position.z)), 0.2);
  const dvec3 ambient_only = dvec3(p.albedo) * dvec3(p.scene.ambient);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(frame.surface.at(32, 24)[c], ambient_only[c], 1e-6);
}

// ---- (f) degenerate configurations -------------------------------------------

TEST(Reference, CameraInsideTheSpotConeIsFinite) {
  Scene scene = fog_scene(Color(0.05f), Color(0.01f));
  scene.camera = camera({0, 1, 0}, {0, 1, -5});
  scene.lights = {spot_light({0, 5, 0}, {0, 0, 0}, Color(100.0f), 30.0f)};
  scene.meshes = {quad_y(0.0, 10.0, Color(0.5f))};
  const Images frame = render(scene, 32, 24);
  expect_finite_and_non_negative(frame, "camera in cone");
  EXPECT_EQ(frame.nonfinite, 0);
  EXPECT_GT(total(frame.airlight), 0.0);
}

TEST(Reference, LightExactlyOnAViewRayIsFinite) {
  // Odd image: the centre pixel's ray is exactly the axis (0, 0, −1) and passes
  // through the light. The true airlight there diverges like ∫dx/x²; any finite
  // value is acceptable, only NaN/Inf/negative are not.
  Scene scene = fog_scene(Color(0.05f), Color(0.01f));
  scene.camera = camera({0, 0, 0}, {0, 0, -1});
  scene.lights = {point_light({0, 0, -5}, Color(100.0f)), spot_light({0, 0, -3}, {0, 0, -10}, Color(50.0f), 20.0f)};
  const Images frame = render(scene, 33, 25);
  const optics::Ray centre = pixel_ray(scene, frame.airlight, 16, 12);
  ASSERT_EQ(centre.dir, dvec3(0, 0, -1));
  expect_finite_and_non_negative(frame, "light on a view ray");
}

TEST(Reference, LightBehindTheCameraIsFinite) {
  Scene scene = fog_scene(Color(0.05f), Color(0.01f));
  scene.lights = {point_light({0, 1, 9}, Color(100.0f)), spot_light({0, 1.5f, 7}, {0, 0, 0}, Color(100.0f), 25.0f)};
  scene.meshes = {quad_y(0.0, 10.0, Color(0.5f))};
  const Images frame = render(scene, 32, 24);
  expect_finite_and_non_negative(frame, "light behind camera");
  EXPECT_EQ(frame.nonfinite, 0);
  EXPECT_GT(total(frame.airlight), 0.0);
}

TEST(Reference, LightInsideAClosedBoxLeaksNothing) {
  Scene scene = fog_scene(Color(0.05f), Color(0.01f));
  scene.lights = {point_light({0, 1, 0}, Color(100.0f))};
  scene.meshes = {box({-1, 0, -1}, {1, 2, 1})};
  const Images frame = render(scene, 32, 24);
  expect_finite_and_non_negative(frame, "light in a box");
  // Watertight robust traversal: not one occlusion ray slips between the faces.
  EXPECT_EQ(total(frame.airlight), 0.0);
  EXPECT_EQ(total(frame.surface), 0.0);
}

TEST(Reference, DirectionalLightThroughFogIsFinite) {
  Scene scene = fog_scene(Color(0.05f), Color(0.01f));
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1, 0.2f));
  sun.irradiance = Color(2.0f);
  scene.lights = {sun};
  scene.meshes = {quad_y(0.0, 10.0, Color(0.5f)), sphere({0, 1.5f, 0}, 0.7f)};
  const Images frame = render(scene, 32, 24);
  expect_finite_and_non_negative(frame, "directional");
  EXPECT_EQ(frame.nonfinite, 0);
  EXPECT_GT(total(frame.airlight), 0.0);
}

// ---- API details ---------------------------------------------------------------

TEST(Reference, CompositeIsSurfacePlusAirlight) {
  const Images frame = render(shadowed_shaft(), 16, 12);
  for (size_t k = 0; k < frame.composite.pixels.size(); ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_FLOAT_EQ(frame.composite.pixels[k][c], frame.surface.pixels[k][c] + frame.airlight.pixels[k][c]);
}

// The viewer follows a background reference through Control and stops it.
TEST(Reference, ControlCountsTilesAndCancels) {
  Control control;
  render(shadowed_shaft(), 40, 30, {}, &control);
  EXPECT_GT(control.total.load(), 1);
  EXPECT_EQ(control.done.load(), control.total.load());
  Control cancelled;
  cancelled.cancel = true;
  EXPECT_THROW(render(shadowed_shaft(), 40, 30, {}, &cancelled), Cancelled);
  EXPECT_EQ(cancelled.done.load(), 0);
}

TEST(Reference, BadMeshesAndSizesAreFailures) {
  Scene scene = fog_scene(Color(0.05f), Color(0.01f));
  scene.meshes = {quad_y(0.0, 1.0, Color(0.5f))};
  scene.meshes[0].triangles.push_back({0, 1, 7});
  EXPECT_THROW(render(scene, 4, 4), Failure);
  EXPECT_THROW(render(fog_scene(Color(0.05f), Color(0.01f)), 0, 4), Failure);
}

}  // namespace
}  // namespace airlight::reference
