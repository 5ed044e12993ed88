// Built-in scenes (DESIGN §4): the documents' test scenes, rebuilt from their
// descriptions (the figures did not survive), lit so that the airlight pass is
// roughly 0.05–1 W/(m²·sr) in the shaft at the default camera and exposure 1.
#include "scene/light_defaults.hpp"
#include "scene/mesh_build.hpp"
#include "scene/shapes.hpp"

#include <airlight/error.hpp>
#include <airlight/scene.hpp>
#include <functional>
#include <glm/geometric.hpp>
#include <map>

namespace airlight {
namespace {

using namespace scene_mesh;

Mesh place(Mesh mesh, const Transform& transform, Color albedo, const std::string& name) {
  apply(transform, mesh);
  mesh.albedo = albedo;
  mesh.name = name;
  return mesh;
}

Mesh place(Mesh mesh, Color albedo, const std::string& name) {
  return place(std::move(mesh), Transform{}, albedo, name);
}

Light spot(glm::vec3 position, glm::vec3 target, Color intensity, float cone_deg,
           float edge_deg = 0.0f) {
  Light light;
  light.type = LightType::spot;
  light.position = position;
  light.direction = glm::normalize(target - position);
  light.intensity = intensity;
  light.cone_deg = cone_deg;
  light.edge_deg = edge_deg;
  light.gobo_up = scene_light::default_gobo_up(light.direction);
  return light;
}

Phase single_lobe(PhaseType type, float g = 0.0f) { return Phase{{PhaseLobe{type, g, 1.0f}}}; }

// A thick floor slab: a closed box is friendlier to silhouette methods than a plane.
Mesh floor_slab(float half_size, Color albedo) {
  return place(make_box({-half_size, -0.2f, -half_size}, {half_size, 0.0f, half_size}), albedo,
               "floor");
}

// Dobashi et al. 2000, Fig. 7a: a teapot under one spotlight; the teapot clips
// the shaft. The spot shines from the upper left onto a teapot on a pedestal,
// so the teapot's volumetric shadow is a dark wedge in the fog to its right.
Scene teapot_spot() {
  Scene s;
  s.name = "teapot_spot";
  s.camera.position = {0.0f, 2.4f, 8.0f};
  s.camera.look_at = {0.3f, 1.4f, 0.0f};
  s.medium.sigma_s = Color(0.06f);
  s.medium.sigma_a = Color(0.01f);
  // Isotropic and hard-edged (Nilsson eq. 2.9), so the unoccluded airlight has a
  // closed form (Sun et al. 2005) that tests hold the reference against.
  s.medium.phase = single_lobe(PhaseType::isotropic);
  s.lights.push_back(spot({-4.0f, 5.5f, -0.5f}, {0.4f, 0.6f, 0.0f}, Color(500.0f), 25.0f));
  s.meshes.push_back(floor_slab(10.0f, Color(0.5f)));
  s.meshes.push_back(place(make_cylinder({0.0f, 0.0f, 0.0f}, 0.35f, 1.0f, 32), Color(0.5f),
                           "pedestal"));
  Transform t;
  t.translate = {0.0f, 1.0f, 0.0f};
  t.rotate_deg = {0.0f, 20.0f, 0.0f};
  t.scale = 1.2f;
  s.meshes.push_back(place(make_teapot(8), t, Color(0.8f, 0.75f, 0.65f), "teapot"));
  return s;
}

// Biri et al. 2006, §6 (after Dobashi et al. 2002): a sphere beyond a spot
// light, whose shadow cuts the beam. 32 segments give the 32-edge silhouette
// the paper reports.
Scene biri_sphere() {
  Scene s;
  s.name = "biri_sphere";
  s.camera.position = {0.0f, 2.2f, 7.5f};
  s.camera.look_at = {0.0f, 2.0f, 0.0f};
  s.medium.sigma_s = Color(0.08f);
  s.lights.push_back(spot({0.0f, 4.5f, 0.0f}, {0.0f, 0.0f, 0.0f}, Color(200.0f), 30.0f));
  s.meshes.push_back(floor_slab(6.0f, Color(0.6f)));
  s.meshes.push_back(place(make_sphere({0.0f, 3.0f, 0.0f}, 0.5f, 32), Color(0.7f), "sphere"));
  return s;
}

// Nilsson 2008, §6 "Toplight": a spot straight down, orthogonal to the view,
// over a few simple objects in front of a backplate, with his simplified light
// model (I / (a1 r² + a0), no extinction, isotropic).
Scene nilsson_toplight() {
  Scene s;
  s.name = "nilsson_toplight";
  s.camera.position = {0.0f, 2.5f, 9.0f};
  s.camera.look_at = {0.0f, 2.3f, 0.0f};
  s.medium.sigma_s = Color(0.1f);
  s.light_model = {LightModelType::simplified, 1.0f, 1.0f};
  s.lights.push_back(spot({0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, Color(80.0f), 30.0f));
  s.meshes.push_back(floor_slab(6.0f, Color(0.6f)));
  s.meshes.push_back(place(make_box({-6.0f, 0.0f, -2.2f}, {6.0f, 6.0f, -2.0f}), Color(0.6f),
                           "backplate"));
  s.meshes.push_back(place(make_box({-1.3f, 2.4f, -0.4f}, {-0.5f, 2.8f, 0.4f}), Color(0.7f),
                           "floating box"));
  s.meshes.push_back(place(make_sphere({0.8f, 2.0f, 0.2f}, 0.45f, 16), Color(0.7f), "sphere"));
  s.meshes.push_back(place(make_cylinder({0.0f, 0.0f, -0.8f}, 0.5f, 1.0f, 16), Color(0.7f),
                           "pedestal"));
  return s;
}

// Several lights at once (the ray-marching issue): a point light inside a cage
// of four pillars — shadows in every horizontal direction, so it needs a cube
// shadow map (Tóth §4) — a spot on a sphere, and a low sun. A sum of lobes
// exercises the phase-function sum.
Scene three_lights() {
  Scene s;
  s.name = "three_lights";
  s.camera.position = {0.0f, 2.6f, 9.0f};
  s.camera.look_at = {0.0f, 1.3f, 0.0f};
  s.medium.sigma_s = Color(0.05f, 0.05f, 0.06f);
  s.medium.sigma_a = Color(0.01f);
  s.medium.phase = Phase{{PhaseLobe{PhaseType::rayleigh, 0.0f, 0.3f},
                          PhaseLobe{PhaseType::henyey_greenstein, 0.4f, 0.7f}}};
  Light point;
  point.type = LightType::point;
  point.position = {-1.5f, 1.6f, 0.0f};
  point.intensity = Color(40.0f, 32.0f, 24.0f);
  s.lights.push_back(point);
  s.lights.push_back(spot({3.5f, 5.0f, 1.0f}, {2.0f, 0.0f, -0.5f}, Color(150.0f, 170.0f, 220.0f), 20.0f, 3.0f));
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.5f, -1.0f, -0.3f));
  sun.irradiance = Color(0.6f, 0.55f, 0.45f);
  s.lights.push_back(sun);
  s.meshes.push_back(floor_slab(8.0f, Color(0.5f)));
  for (const float x : {-2.3f, -0.7f})
    for (const float z : {-0.8f, 0.8f})
      s.meshes.push_back(place(make_box({x - 0.15f, 0.0f, z - 0.15f}, {x + 0.15f, 2.6f, z + 0.15f}), Color(0.6f),
                               "pillar"));
  s.meshes.push_back(place(make_box({-2.45f, 2.6f, -0.95f}, {-0.55f, 2.8f, 0.95f}), Color(0.6f), "roof"));
  s.meshes.push_back(place(make_sphere({2.0f, 0.8f, -0.5f}, 0.6f, 32), Color(0.7f, 0.6f, 0.5f), "sphere"));
  return s;
}

const std::map<std::string, std::function<Scene()>>& builtins() {
  static const std::map<std::string, std::function<Scene()>> scenes = {
      {"teapot_spot", teapot_spot},
      {"biri_sphere", biri_sphere},
      {"nilsson_toplight", nilsson_toplight},
      {"three_lights", three_lights}};
  return scenes;
}

}  // namespace

Scene builtin_scene(const std::string& name) {
  const auto it = builtins().find(name);
  if (it == builtins().end()) throw InputError("<builtin>", name, "unknown built-in scene");
  return it->second();
}

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : builtins()) names.push_back(entry.first);
  return names;
}

}  // namespace airlight
