// The built-in scenes after Dobashi et al. 2000 (builtin_families.hpp).
#include "scene/builtin_families.hpp"
#include "scene/builtin_parts.hpp"
#include "scene/gobo_patterns.hpp"

#include <glm/geometric.hpp>
#include <memory>

namespace airlight::scene_builtin {

using namespace scene_mesh;

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

namespace {

// `light` projecting `gobo`, its light map (Dobashi et al. 2000, §4).
Light with_gobo(Light light, std::shared_ptr<const Image> gobo) {
  light.gobo = std::move(gobo);
  return light;
}

// The set of Dobashi et al. 2000, Fig. 7b: a raised stage (a black deck 1 m
// above the auditorium floor, deep enough to hold every spot's pool of light)
// before a back wall; a crate, a column and a ball on a plinth stand in the
// light to cut volumetric shadows into the shafts; the truss holds the spots.
void add_stage_set(Scene& s) {
  add_box(s, {-6.0f, -1.0f, -6.0f}, {6.0f, 0.0f, 2.0f}, Color(0.25f), "stage floor");
  add_box(s, {-9.0f, -1.2f, 2.0f}, {9.0f, -1.0f, 13.0f}, Color(0.35f), "auditorium floor");
  add_box(s, {-7.0f, -1.0f, -6.4f}, {7.0f, 7.0f, -6.0f}, Color(0.45f), "back wall");
  add_box(s, {-5.0f, 5.5f, 1.35f}, {5.0f, 5.7f, 1.65f}, Color(0.3f), "truss");
  add_box(s, {-2.3f, 0.0f, -2.4f}, {-1.3f, 1.0f, -1.4f}, Color(0.55f, 0.45f, 0.35f), "crate");
  s.meshes.push_back(place(make_cylinder({1.9f, 0.0f, -2.5f}, 0.35f, 2.4f, 24), Color(0.7f), "column"));
  add_box(s, {3.0f, 0.0f, -1.6f}, {3.6f, 0.8f, -1.0f}, Color(0.6f), "plinth");
  s.meshes.push_back(place(make_sphere({3.3f, 1.2f, -1.3f}, 0.4f, 24), Color(0.75f), "ball"));
}

// Dobashi Fig. 7b: "There are 5 spotlights. Some of the spotlights are special
// effects lights, polka dots." Five spots hang under the truss over the front
// edge of the stage and point down and back at different angles, in several
// colours; two throw polka dots from 64×64 light maps (the light-map size of
// Fig. 7b in Dobashi's Table 1). The dots are hard-edged, the plain spots soft.
// The white spot lays its big dots near the front of the stage, where each
// still covers several pixels of a 128×96 image (floor pattern comparisons).
void add_stage_lights(Scene& s) {
  const auto big_dots = std::make_shared<const Image>(scene_gobo::polka_dots(64, 4, 0.7f));
  const auto small_dots = std::make_shared<const Image>(scene_gobo::polka_dots(64, 5, 0.55f));
  const float y = 5.3f, z = 1.5f;  // just below the truss
  s.lights.push_back(spot({-4.0f, y, z}, {-3.3f, 0.0f, -1.0f}, Color(300.0f, 240.0f, 160.0f), 16.0f, 3.0f));
  s.lights.push_back(
      with_gobo(spot({-2.0f, y, z}, {-1.6f, 0.0f, -1.8f}, Color(700.0f, 160.0f, 600.0f), 20.0f), small_dots));
  s.lights.push_back(
      with_gobo(spot({0.0f, y, z}, {0.0f, 0.0f, -0.6f}, Color(800.0f, 800.0f, 900.0f), 25.0f), big_dots));
  s.lights.push_back(spot({2.0f, y, z}, {2.1f, 0.0f, -2.6f}, Color(400.0f, 240.0f, 60.0f), 14.0f, 2.0f));
  s.lights.push_back(spot({4.0f, y, z}, {3.0f, 0.0f, -1.2f}, Color(120.0f, 300.0f, 260.0f), 20.0f, 3.0f));
}

}  // namespace

// Dobashi et al. 2000, Fig. 7b, "an example of the lighting design for
// stages", seen from high in the audience with all five shafts in view through
// a theatre haze that scatters a little forward.
Scene stage() {
  Scene s;
  s.name = "stage";
  s.camera.position = {0.0f, 5.5f, 11.5f};
  s.camera.look_at = {0.0f, 1.9f, -1.0f};
  s.medium.sigma_s = Color(0.05f);
  s.medium.sigma_a = Color(0.005f);
  s.medium.phase = single_lobe(PhaseType::henyey_greenstein, 0.3f);
  s.ambient = Color(0.02f);  // a dim house light, so that the set reads
  add_stage_set(s);
  add_stage_lights(s);
  return s;
}

// Dobashi et al. 2000, Fig. 8b: "the sunlight passes through stained glass
// windows in a dusty room. … a pattern of the stained glass is used as the
// light map texture for the parallel light source". An 8 m × 3.5 m × 6 m room
// with one tall window in its back wall; the sun slants down through it in a
// bounded beam carrying a 128×128 stained-glass light map (Table 1's size for
// Fig. 8b), so the dust shows coloured shafts and the floor a coloured window.
// A table and a pillar stand in the beam. The camera stands in the room looking
// back at the window across the shafts, which the dust scatters forward toward
// it. A bright sun on dark stone lifts the shafts to the airlight level of the
// other scenes (builtin_families.hpp) without burning out the lit floor; an
// ambient term shows the rest of the room.
Scene stained_glass() {
  Scene s;
  s.name = "stained_glass";
  s.camera.position = {2.0f, 1.5f, 1.8f};
  s.camera.look_at = {0.0f, 1.0f, -3.0f};
  s.camera.fov_y_deg = 60.0f;
  s.medium.sigma_s = Color(0.15f);
  s.medium.sigma_a = Color(0.01f);
  s.medium.phase = single_lobe(PhaseType::henyey_greenstein, 0.4f);
  s.ambient = Color(0.12f);
  const Extent inside{{-4.0f, 0.0f, -3.0f}, {4.0f, 3.5f, 3.0f}};
  const float wall = 0.25f;
  const Extent window{{-0.8f, 1.0f, inside.min.z - wall}, {0.8f, 3.0f, inside.min.z}};
  add_pieces(s, make_room(inside, window, wall), Color(0.32f, 0.3f, 0.27f));  // dark stone
  add_pieces(s, make_table({0.1f, 0.75f, -1.3f}, {1.2f, 0.7f}), Color(0.45f, 0.3f, 0.2f));
  s.meshes.push_back(
      place(make_cylinder({-0.35f, 0.0f, -2.5f}, 0.15f, inside.max.y, 24), Color(0.6f), "pillar"));
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.25f, -0.71f, 0.66f));  // 45° high
  sun.irradiance = Color(24.0f, 22.5f, 19.5f);
  sun.gobo = std::make_shared<const Image>(scene_gobo::stained_glass(128, 128));
  sun.gobo_up = {0.0f, 1.0f, 0.0f};  // the window's top toward the sky: the pattern stands upright
  sun.beam = beam_through(sun, window, inside, 0.05f);
  s.lights.push_back(sun);
  return s;
}

}  // namespace airlight::scene_builtin
