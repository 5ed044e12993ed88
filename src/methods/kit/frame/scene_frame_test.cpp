// The shared frame (methods/kit/frame/scene_frame.hpp) against the CPU: the G-buffer distance
// against the analytic ray hit, the surface pass against reference::render.
#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "methods/kit/frame/scene_frame.hpp"
#include "methods/kit/frame/shadows/shadow_projection.hpp"

#include "geometry/camera.hpp"
#include "reference/reference.hpp"

#include <airlight/scene.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

namespace airlight::kit {
namespace {

constexpr int width = 128, height = 96;

// Relative RMSE of docs/design.md §6: sqrt(mean((m − r)²)) / mean(r) over pixels and channels.
const auto rel_rmse = [](const Image& m, const Image& r) {
  double squares = 0.0, sum = 0.0;
  for (size_t i = 0; i < r.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double d = double(m.pixels[i][c]) - r.pixels[i][c];
      squares += d * d;
      sum += r.pixels[i][c];
    }
  const double n = 3.0 * r.pixels.size();
  return std::sqrt(squares / n) / (sum / n);
};

struct Rendered {
  Image distance, surface, albedo;
};

Rendered render_frame(const Scene& scene, int w = width, int h = height, FrameSettings settings = {}) {
  gpu::Context& context = gpu::Context::headless();
  SceneFrame frame;
  frame.prepare(scene);
  PassTimer timer;
  frame.render(frame_inputs(scene, w, h), settings, nullptr, {}, timer);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  Rendered r{gpu::read_image(frame.distance(), w, h), gpu::read_image(frame.surface(), w, h), gpu::read_image(frame.albedo(), w, h)};
  const auto times = timer.results();
  EXPECT_EQ(times.size(), 3u);
  context.check("frame_test");
  return r;
}

Mesh quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, Color albedo) {
  Mesh mesh;
  mesh.name = "quad";
  mesh.positions = {a, b, c, d};
  const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
  mesh.normals.assign(4, n);
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.albedo = albedo;
  return mesh;
}

// An axis-aligned box with outward faces (4 vertices each).
Mesh box(glm::vec3 lo, glm::vec3 hi, Color albedo) {
  Mesh mesh;
  mesh.name = "box";
  mesh.albedo = albedo;
  auto face = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    const Mesh q = quad(a, b, c, d, albedo);
    const auto base = static_cast<unsigned>(mesh.positions.size());
    for (int k = 0; k < 4; ++k) {
      mesh.positions.push_back(q.positions[k]);
      mesh.normals.push_back(q.normals[k]);
    }
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
  };
  const glm::vec3 l = lo, h = hi;
  face({l.x, l.y, h.z}, {h.x, l.y, h.z}, {h.x, h.y, h.z}, {l.x, h.y, h.z});  // +z
  face({h.x, l.y, l.z}, {l.x, l.y, l.z}, {l.x, h.y, l.z}, {h.x, h.y, l.z});  // -z
  face({h.x, l.y, h.z}, {h.x, l.y, l.z}, {h.x, h.y, l.z}, {h.x, h.y, h.z});  // +x
  face({l.x, l.y, l.z}, {l.x, l.y, h.z}, {l.x, h.y, h.z}, {l.x, h.y, l.z});  // -x
  face({l.x, h.y, h.z}, {h.x, h.y, h.z}, {h.x, h.y, l.z}, {l.x, h.y, l.z});  // +y
  face({l.x, l.y, l.z}, {h.x, l.y, l.z}, {h.x, l.y, h.z}, {l.x, l.y, h.z});  // -y
  return mesh;
}

Light point_light(glm::vec3 position, float intensity) {
  Light light;
  light.type = LightType::point;
  light.position = position;
  light.intensity = Color(intensity);
  return light;
}

Light spot_light(glm::vec3 position, glm::vec3 target, float intensity, float cone_deg, float edge_deg) {
  Light light;
  light.type = LightType::spot;
  light.position = position;
  light.direction = glm::normalize(target - position);
  light.intensity = Color(intensity);
  light.cone_deg = cone_deg;
  light.edge_deg = edge_deg;
  light.gobo_up = {0, 0, -1};
  return light;
}

Light directional_light(glm::vec3 direction, float irradiance) {
  Light light;
  light.type = LightType::directional;
  light.direction = glm::normalize(direction);
  light.irradiance = Color(irradiance);
  return light;
}

// A coloured, non-square gobo whose texels all differ: any flip or swap of u, v shows.
std::shared_ptr<const Image> test_gobo() {
  auto gobo = std::make_shared<Image>(8, 6);
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x)
      gobo->at(x, y) = Color(0.1f + 0.9f * x / 7.0f, 0.1f + 0.9f * y / 5.0f, (x + y) % 2 ? 1.0f : 0.2f);
  return gobo;
}

// A floor (y = 0) with a box standing on it and a pillar, lit by one light: the
// box's and the pillar's shadows fall on the floor and on each other.
Scene shadow_scene(const Light& light) {
  Scene s;
  s.name = "shadow_scene";
  s.camera.position = {0.0f, 3.0f, 7.0f};
  s.camera.look_at = {0.0f, 0.5f, 0.0f};
  s.medium.sigma_s = Color(0.05f);
  s.medium.sigma_a = Color(0.02f);
  s.ambient = Color(0.02f);
  s.meshes.push_back(quad({-6, 0, 6}, {6, 0, 6}, {6, 0, -6}, {-6, 0, -6}, Color(0.6f)));
  s.meshes.push_back(box({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}, Color(0.7f, 0.6f, 0.5f)));
  s.meshes.push_back(box({1.2f, 0.0f, -1.5f}, {1.5f, 2.5f, -1.2f}, Color(0.5f, 0.6f, 0.7f)));
  s.lights.push_back(light);
  return s;
}

// Pixels whose radiance differs from the reference's by more than 1% (+1e-4 absolute).
double mismatched_fraction(const Image& m, const Image& r) {
  int count = 0;
  for (size_t i = 0; i < r.pixels.size(); ++i)
    if (glm::length(m.pixels[i] - r.pixels[i]) > 0.01f * glm::length(r.pixels[i]) + 1e-4f) ++count;
  return double(count) / r.pixels.size();
}

// The surface pass against reference::render's surface: the relative RMSE, and
// the fraction of pixels that differ at all (shadow-edge pixels flipping between
// lit and shadowed through the shadow map's texels; everything else must agree).
void expect_surface_close(const Scene& scene, double tolerance, double max_mismatched, const char* reason) {
  const Rendered gpu = render_frame(scene);
  const reference::Images cpu = reference::render(scene, width, height, {.airlight = false});
  const double error = rel_rmse(gpu.surface, cpu.surface);
  const double mismatched = mismatched_fraction(gpu.surface, cpu.surface);
  std::printf("%s: surface rel. RMSE %.5f (bound %.3f), %.3f%% pixels off by > 1%% (bound %.2f%%)\n",
              scene.name.c_str(), error, tolerance, 100 * mismatched, 100 * max_mismatched);
  EXPECT_LT(error, tolerance) << reason;
  EXPECT_LE(mismatched, max_mismatched) << reason;
}

// ---- G-buffer -----------------------------------------------------------------

TEST(SceneFrame, GbufferDistanceIsTheRayHitOrTheFarPlane) {
  Scene s;
  s.camera.position = {0.3f, 2.0f, 6.0f};
  s.camera.look_at = {0.0f, 0.4f, 0.0f};
  s.camera.far = 30.0f;
  // A tilted plane through the origin, normal n: the hit is t = −(o − p0)·n / (d·n).
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.1, 1.0, 0.2));
  const glm::dvec3 u = glm::normalize(glm::cross(n, glm::dvec3(0, 0, 1))), v = glm::cross(u, n);
  auto corner = [&](double a, double b) { return glm::vec3(8.0 * a * u + 8.0 * b * v); };
  s.meshes.push_back(quad(corner(-1, -1), corner(1, -1), corner(1, 1), corner(-1, 1), Color(0.5f)));
  const Rendered gpu = render_frame(s);
  int hits = 0, misses = 0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const optics::Ray ray = geometry::primary_ray(s.camera, width, height, i + 0.5, j + 0.5);
      const double t = -glm::dot(ray.origin, n) / glm::dot(ray.dir, n);
      const glm::dvec3 p = ray.origin + t * ray.dir;
      const bool on_quad = t > 0.0 && std::abs(glm::dot(p, u)) < 8.0 && std::abs(glm::dot(p, v)) < 8.0 &&
                           t < geometry::far_distance(s.camera, ray.dir);
      const double gpu_t = gpu.distance.at(i, j).x;
      const bool gpu_hit = gpu.albedo.at(i, j).x > 0.0f;
      // Pixels whose centre is within 1e-3 of the quad's edge may go either way.
      const double edge = std::max(std::abs(glm::dot(p, u)), std::abs(glm::dot(p, v)));
      if (std::abs(edge - 8.0) < 1e-3) continue;
      ASSERT_EQ(gpu_hit, on_quad) << "pixel " << i << ", " << j;
      const double expected = on_quad ? t : geometry::far_distance(s.camera, ray.dir);
      // Float: the interpolated position carries ~1e-7 relative error per coordinate
      // (scene scale ~10 m), so 1e-5 relative leaves two orders of margin.
      EXPECT_NEAR(gpu_t, expected, 1e-5 * expected) << "pixel " << i << ", " << j;
      ++(on_quad ? hits : misses);
    }
  EXPECT_GT(hits, width * height / 4);
  EXPECT_GT(misses, width * height / 20);
}

// ---- surface pass -----------------------------------------------------------------

// Shadow-edge pixels: at 128×96 a 1024² map's texel (a few cm on the floor)
// flips 2–3 pixels of the teapot's shadow edge (they vanish at 8192²); each adds
// ~1.5% to the RMSE because the image's mean radiance is low (mostly dark).
TEST(SceneFrame, SurfaceMatchesReferenceOnTeapotSpot) {
  expect_surface_close(builtin_scene("teapot_spot"), 0.05, 0.001,
                       "2–3 shadow-edge pixels through the 1024² map's texels");
}

TEST(SceneFrame, SurfaceMatchesReferenceOnBiriSphere) {
  expect_surface_close(builtin_scene("biri_sphere"), 0.02, 0.001, "the sphere's shadow edge through a 1024² map");
}

TEST(SceneFrame, CubeShadowMapForAPointLight) {
  expect_surface_close(shadow_scene(point_light({0.5f, 2.2f, 0.8f}, 30.0f)), 0.02, 0.003,
                       "shadow edges of the box and pillar through 1024² cube faces");
}

TEST(SceneFrame, DirectionalLightOrthographicMapAndVolumeOnItsLeg) {
  Scene s = shadow_scene(directional_light({0.4f, -1.0f, -0.3f}, 2.0f));
  s.name = "directional";
  // A volume the light crosses on its way to the floor (docs/design.md §1: the only
  // extinction on a directional light's leg) and the view rays cross too.
  Volume v;
  v.min = {-3.0f, 0.5f, -3.0f};
  v.max = {0.0f, 2.0f, 3.0f};
  v.sigma_s = Color(0.3f, 0.1f, 0.05f);
  v.sigma_a = Color(0.1f);
  s.volumes.push_back(v);
  expect_surface_close(s, 0.03, 0.003,
                       "2 shadow-edge pixels through the 1024² orthographic map over the scene's 12 m bounds "
                       "(1.2 cm texels)");
}

TEST(SceneFrame, SpotWithGoboAndSmoothEdge) {
  Light light = spot_light({-1.0f, 4.0f, 1.5f}, {0.3f, 0.0f, -0.5f}, 60.0f, 35.0f, 8.0f);
  light.gobo = test_gobo();
  Scene s = shadow_scene(light);
  s.name = "gobo_spot";
  expect_surface_close(s, 0.03, 0.003, "2 shadow-edge pixels through a 1024² map of a 70° field (measured 0.017)");
}

// A beam (a directional light bounded to a box) with a gobo across its
// aperture, tilted onto the floor: the gobo's image, the beam's edges and the
// box's and pillar's shadows inside it. The shadow map spans only the 4 m × 3 m
// aperture (frame.cpp directional_projection).
Light beam_light(const glm::vec3& direction) {
  Light light = directional_light(direction, 3.0f);
  light.gobo_up = {0, 0, -1};
  light.beam = Beam{{0.3f, 4.0f, 0.2f}, {4.0f, 3.0f}, 7.0f};
  light.gobo = test_gobo();
  return light;
}

TEST(SceneFrame, BeamWithGoboOntoTheFloor) {
  Scene s = shadow_scene(beam_light({0.3f, -1.0f, -0.2f}));
  s.name = "beam";
  // Only the beam's footprint is lit, so the image's mean is low and each
  // pixel flipping at a shadow edge weighs much: all of the error is two
  // pixels whose centres lie 2 mm inside the box's shadow edge (x = 0.8), half
  // a texel of the map (1024² over the 4 m aperture: 4 mm texels), whose
  // nearest texel lies outside the shadow. Every other pixel, gobo and beam
  // edges included, agrees to 1%.
  expect_surface_close(s, 0.15, 0.001, "2 pixels 2 mm inside the box's shadow edge, half a shadow-map texel");
}

TEST(SceneFrame, WideSpotUsesACubeMap) {
  static_assert(wide_spot_deg < 75.0f);
  Scene s = shadow_scene(spot_light({0.3f, 3.0f, 1.0f}, {0.0f, 0.0f, -0.5f}, 40.0f, 75.0f, 10.0f));
  s.name = "wide_spot";
  expect_surface_close(s, 0.02, 0.003, "shadow edges through 1024² cube faces");
}

TEST(SceneFrame, SimplifiedLightModel) {
  // The pedestal's bottom cap is coplanar with the floor's top: where both are
  // visible (2 pixels at the foot of its silhouette) the depth test and Embree
  // pick different ones, lit floor against the cap whose shadow ray starts
  // inside the pedestal. 2 pixels of 10× the mean radiance give RMSE ≈ 0.14.
  expect_surface_close(builtin_scene("nilsson_toplight"), 0.2, 0.001,
                       "2 pixels of coplanar floor and pedestal cap");
}

TEST(SceneFrame, SeveralLightsAndAmbient) {
  Scene s = shadow_scene(point_light({-1.5f, 2.0f, 1.0f}, 15.0f));
  s.name = "three_lights";
  s.lights.push_back(spot_light({2.0f, 4.0f, 2.0f}, {0.0f, 0.0f, 0.0f}, 50.0f, 25.0f, 0.0f));
  s.lights.push_back(directional_light({-0.2f, -1.0f, -0.5f}, 0.5f));
  s.ambient = Color(0.05f, 0.04f, 0.03f);
  expect_surface_close(s, 0.02, 0.005, "shadow edges of three lights' maps");
}

// The scene-wide flags for #if (scene.glsl) name what some light or medium of
// the scene has: stage's five spots, soft and hard, two with gobos, in an
// anisotropic medium; three_lights' point, soft spot and sun; Biri's media,
// isotropic; Nilsson's simplified model in an isotropic medium.
TEST(SceneFrame, ScenewideFlagsNameWhatSomeLightHas) {
  gpu::Context& context = gpu::Context::headless();
  const auto flags_of = [](const char* name) {
    const Scene scene = builtin_scene(name);
    SceneFrame frame;
    frame.prepare(scene);
    PassTimer timer;
    frame.render(frame_inputs(scene, 8, 8), {}, nullptr, {}, timer);
    std::string flags;
    for (const char* flag : {"HAS_POINT_LIGHT", "HAS_SPOT_LIGHT", "HAS_DIRECTIONAL_LIGHT", "HAS_SMOOTH_SPOT",
                             "HAS_HARD_SPOT", "HAS_GOBO", "SIMPLIFIED_MODEL", "ISOTROPIC_COMPONENTS"}) {
      const std::string key = std::string("#define ") + flag + " ";
      const size_t at = frame.defines().find(key);
      flags += at == std::string::npos ? '?' : frame.defines()[at + key.size()];
    }
    return flags;
  };
  EXPECT_EQ(flags_of("stage"), "01011100");
  EXPECT_EQ(flags_of("three_lights"), "11110000");
  EXPECT_EQ(flags_of("biri_media"), "01001001");
  EXPECT_EQ(flags_of("nilsson_toplight"), "01001011");
  context.check("scene-wide flags");
}

}  // namespace
}  // namespace airlight::kit
