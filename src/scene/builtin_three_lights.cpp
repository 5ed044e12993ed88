// The built-in scene of several lights at once (builtin_families.hpp).
#include "scene/builtin_families.hpp"
#include "scene/builtin_parts.hpp"

#include <glm/geometric.hpp>

namespace airlight::scene_builtin {

using namespace scene_mesh;

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

}  // namespace airlight::scene_builtin
