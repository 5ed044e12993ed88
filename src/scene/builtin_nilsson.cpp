// The built-in scenes after Nilsson 2008 (builtin_families.hpp).
#include "scene/builtin_families.hpp"
#include "scene/builtin_parts.hpp"

#include <glm/geometric.hpp>

namespace airlight::scene_builtin {

using namespace scene_mesh;

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

// Nilsson 2008 §6 "Parallel": the light nearly parallel to the view, so that
// the shafts run away from the eye (where sampling needs the most planes): a
// directional beam from behind and above the camera through a frame of bars
// and boxes, into a haze.
Scene nilsson_parallel() {
  Scene s;
  s.name = "nilsson_parallel";
  s.camera.position = {0.0f, 2.0f, 8.0f};
  s.camera.look_at = {0.0f, 1.6f, 0.0f};
  s.medium.sigma_s = Color(0.06f);
  s.medium.sigma_a = Color(0.01f);
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.1f, -0.35f, -1.0f));
  sun.irradiance = Color(6.0f);
  sun.gobo_up = {0.0f, 1.0f, 0.0f};
  sun.beam = beam_through(sun, {{-2.0f, 1.0f, 3.9f}, {2.0f, 4.0f, 4.1f}}, {{-6.0f, -0.2f, -8.0f}, {6.0f, 6.0f, 6.0f}},
                          0.05f);
  s.lights.push_back(sun);
  s.meshes.push_back(floor_slab(8.0f, Color(0.5f)));
  for (int k = 0; k < 3; ++k)  // bars across the beam's mouth
    s.meshes.push_back(place(make_box({-2.0f, 1.6f + 0.8f * k, 3.0f}, {2.0f, 1.75f + 0.8f * k, 3.15f}), Color(0.6f),
                             "bar"));
  s.meshes.push_back(place(make_box({-0.9f, 0.0f, -1.0f}, {-0.3f, 1.2f, -0.4f}), Color(0.7f), "box"));
  s.meshes.push_back(place(make_sphere({0.8f, 1.0f, -2.0f}, 0.5f, 16), Color(0.7f), "sphere"));
  return s;
}

// Nilsson 2008 §6 "Multiple": many objects under one spot from above, so that
// the beam tree grows: a 5×5 grid of boxes and spheres at two heights.
Scene nilsson_multiple() {
  Scene s;
  s.name = "nilsson_multiple";
  s.camera.position = {0.0f, 2.8f, 9.0f};
  s.camera.look_at = {0.0f, 2.0f, 0.0f};
  s.medium.sigma_s = Color(0.08f);
  s.lights.push_back(spot({0.0f, 6.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, Color(400.0f), 35.0f));
  s.meshes.push_back(floor_slab(8.0f, Color(0.6f)));
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const glm::vec3 c(-2.0f + 1.0f * i, (i + j) % 2 ? 3.4f : 2.6f, -2.0f + 1.0f * j);
      Mesh mesh = (i + j) % 2 ? make_sphere(c, 0.22f, 12) : make_box(c - glm::vec3(0.2f), c + glm::vec3(0.2f));
      s.meshes.push_back(place(std::move(mesh), Color(0.7f), (i + j) % 2 ? "sphere" : "box"));
    }
  return s;
}

}  // namespace airlight::scene_builtin
