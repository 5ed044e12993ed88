#pragma once
// Test helpers shared by every method's tests and the kit's (frame, engine,
// light volume, method): rendering a method with settings, the cached
// reference, and a scene built in code that uses every feature of the model.
#include "reference/cache.hpp"
#include "reference/reference.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace airlight::kit::test {

// The method with its settings set from "key=value" assignments, prepared with the scene.
inline std::unique_ptr<Method> prepared(const MethodInfo& info, const Scene& scene,
                                        const std::vector<std::string>& assignments) {
  Settings settings(info.settings);
  for (const auto& a : assignments) settings.set(a, "test");
  auto method = info.create(settings);
  method->prepare(scene);
  return method;
}

inline FrameImages render(const MethodInfo& info, const Scene& scene, const std::vector<std::string>& assignments,
                          int width, int height) {
  return airlight::render(*prepared(info, scene, assignments), scene, width, height);
}

// The reference's passes from the on-disk cache that every test of one ctest
// run shares: AIRLIGHT_TEST_CACHE, which the reference_cache fixture empties
// before the run (README "Tests and their budget"), so that a scene's
// reference is rendered once per run, not once per test process. Rendered here
// when the variable is unset (a test program run by hand).
inline reference::CachedReference shared_reference(const Scene& scene, int width, int height,
                                                   const reference::Settings& settings = {}) {
  if (const char* dir = std::getenv("AIRLIGHT_TEST_CACHE"); dir && *dir)
    return reference::cached_reference(scene, width, height, dir, settings);
  reference::Images frame = reference::render(scene, width, height, settings);
  return {std::move(frame.airlight), std::move(frame.surface)};
}

// The reference's airlight, read once per scene name and size in a process.
inline const Image& reference_airlight(const Scene& scene, int width, int height) {
  static std::map<std::tuple<std::string, int, int>, Image> cache;
  const auto key = std::make_tuple(scene.name, width, height);
  auto it = cache.find(key);
  if (it == cache.end()) it = cache.emplace(key, shared_reference(scene, width, height).airlight).first;
  return it->second;
}

// The reference with 256 first segments instead of 32: 32 miss thin lit
// slivers beside a spot's apex (at 80×60 two pixels of biri_sphere got 3% too
// much: 0.3663 against 0.3563 from 256 segments, raymarch at N = 4096 and the
// exact methods), which the exact methods' tests would count as their error.
inline Image fine_reference_airlight(const Scene& scene, int width, int height) {
  return shared_reference(scene, width, height, {.min_segments = 256}).airlight;
}

// A method's counter by name (FrameImages::stats), −1 when it reports none.
inline double stat(const FrameImages& frame, const std::string& name) {
  for (const auto& [key, value] : frame.stats)
    if (key == name) return value;
  return -1.0;
}

inline bool all_finite_and_non_negative(const Image& image) {
  return std::all_of(image.pixels.begin(), image.pixels.end(), [](const glm::vec3& p) {
    return std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) && p.r >= 0 && p.g >= 0 && p.b >= 0;
  });
}

inline Mesh box(glm::vec3 lo, glm::vec3 hi, Color albedo) {
  Mesh mesh;
  mesh.name = "box";
  mesh.albedo = albedo;
  for (int k = 0; k < 8; ++k) mesh.positions.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  // Outward faces, counter-clockwise; no normals (the geometric normal shades).
  mesh.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                    {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return mesh;
}

inline Light make_light(LightType type, glm::vec3 position, glm::vec3 direction, float power, float cone_deg = 30.0f,
                        float edge_deg = 0.0f) {
  Light light;
  light.type = type;
  light.position = position;
  light.direction = glm::normalize(direction);
  light.intensity = Color(power);
  light.irradiance = Color(power);
  light.cone_deg = cone_deg;
  light.edge_deg = edge_deg;
  light.gobo_up = std::abs(light.direction.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  return light;
}

inline Phase phase(std::vector<PhaseLobe> lobes) { return Phase{std::move(lobes)}; }

// Floor, a block and a pillar in a medium with a two-lobe phase function and a
// coloured box volume of its own phase, lit by a spot, a point and a directional
// light. The point and spot lights sit behind the eye (≥ 1.5 m from every view
// ray), so that no ray meets a 1/r² peak narrower than its steps: the error left
// is the features', not the light's neighbourhood.
inline Scene every_feature_scene() {
  Scene s;
  s.name = "every_feature";
  s.camera.position = {0.0f, 2.5f, 7.0f};
  s.camera.look_at = {0.0f, 1.2f, 0.0f};
  s.camera.far = 20.0f;
  s.medium.sigma_s = Color(0.05f, 0.06f, 0.08f);
  s.medium.sigma_a = Color(0.02f);
  s.medium.phase = phase({{PhaseType::henyey_greenstein, 0.5f, 0.6f}, {PhaseType::rayleigh, 0.0f, 0.4f}});
  Volume v;
  v.min = {-2.5f, 0.0f, -1.0f};
  v.max = {-0.5f, 3.0f, 1.5f};
  v.sigma_s = Color(0.3f, 0.15f, 0.05f);
  v.sigma_a = Color(0.05f);
  v.phase = phase({{PhaseType::hazy, 0.0f, 1.0f}});
  s.volumes.push_back(v);
  s.meshes.push_back(box({-6, -0.2f, -6}, {6, 0, 6}, Color(0.6f)));
  s.meshes.push_back(box({-0.6f, 0, -0.6f}, {0.6f, 1.0f, 0.6f}, Color(0.7f)));
  s.meshes.push_back(box({1.3f, 0, -1.5f}, {1.6f, 2.5f, -1.2f}, Color(0.7f)));
  s.lights.push_back(make_light(LightType::spot, {-2.0f, 4.5f, 8.0f}, {0.25f, -0.45f, -1.0f}, 300.0f, 15.0f, 3.0f));
  s.lights.push_back(make_light(LightType::point, {1.5f, 3.5f, 7.8f}, {0, -1, 0}, 40.0f));
  s.lights.push_back(make_light(LightType::directional, {}, {0.5f, -1.0f, -0.3f}, 0.3f));
  return s;
}

}  // namespace airlight::kit::test
