// The built-in scenes after Biri et al. 2006 (builtin_families.hpp).
#include "scene/builtin_families.hpp"
#include "scene/builtin_parts.hpp"

#include <array>
#include <utility>

namespace airlight::scene_builtin {

using namespace scene_mesh;

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

// Biri et al. 2006, Fig. 7a: two pens (closed cylinders) crossing above the
// floor under one spot, the upper one's shadow volume passing through the
// lower one's, so that many view rays cross both (shadow in shadow).
Scene biri_pens() {
  Scene s;
  s.name = "biri_pens";
  s.camera.position = {0.5f, 2.0f, 7.0f};
  s.camera.look_at = {0.0f, 1.6f, 0.0f};
  s.medium.sigma_s = Color(0.08f);
  s.medium.sigma_a = Color(0.01f);
  s.lights.push_back(spot({0.3f, 5.0f, 0.2f}, {0.0f, 0.0f, 0.0f}, Color(250.0f), 32.0f));
  s.meshes.push_back(floor_slab(6.0f, Color(0.6f)));
  Transform upper;
  upper.translate = {-0.9f, 3.4f, 0.1f};
  upper.rotate_deg = {0.0f, 25.0f, -80.0f};
  s.meshes.push_back(place(make_cylinder({0.0f, 0.0f, 0.0f}, 0.09f, 1.9f, 24), upper, Color(0.2f, 0.3f, 0.7f),
                           "upper pen"));
  Transform lower;
  lower.translate = {-0.8f, 2.4f, -0.3f};
  lower.rotate_deg = {0.0f, -35.0f, -95.0f};
  s.meshes.push_back(place(make_cylinder({0.0f, 0.0f, 0.0f}, 0.11f, 1.7f, 24), lower, Color(0.7f, 0.2f, 0.2f),
                           "lower pen"));
  return s;
}

// Biri et al. 2006, Fig. 7b: a box under a spot inside three bounded convex
// media of their own colour (red, green and blue scattering) in a thin haze.
Scene biri_media() {
  Scene s;
  s.name = "biri_media";
  s.camera.position = {0.0f, 2.2f, 7.5f};
  s.camera.look_at = {0.0f, 1.6f, 0.0f};
  s.medium.sigma_s = Color(0.02f);
  s.lights.push_back(spot({0.0f, 5.0f, 0.0f}, {0.0f, 0.0f, 0.0f}, Color(300.0f), 35.0f));
  s.meshes.push_back(floor_slab(6.0f, Color(0.6f)));
  s.meshes.push_back(place(make_box({-0.4f, 2.6f, -0.4f}, {0.4f, 3.0f, 0.4f}), Color(0.7f), "box"));
  const std::array<std::pair<glm::vec3, Color>, 3> media{{{{-1.6f, 0.0f, -1.0f}, Color(0.25f, 0.02f, 0.02f)},
                                                          {{-0.5f, 0.0f, -1.0f}, Color(0.02f, 0.25f, 0.02f)},
                                                          {{0.6f, 0.0f, -1.0f}, Color(0.02f, 0.02f, 0.25f)}}};
  for (const auto& [corner, sigma_s] : media) {
    Volume v;
    v.min = corner;
    v.max = corner + glm::vec3(1.0f, 2.4f, 2.0f);
    v.sigma_s = sigma_s;
    v.sigma_a = Color(0.01f);
    s.volumes.push_back(v);
  }
  return s;
}

}  // namespace airlight::scene_builtin
