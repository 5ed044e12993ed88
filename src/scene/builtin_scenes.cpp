// Built-in scenes (docs/design.md §4): the documents' test scenes, rebuilt from their
// descriptions (the figures did not survive), lit so that the airlight pass is
// roughly 0.05–1 W/(m²·sr) in the shaft at the default camera and exposure 1.
#include "scene/gobo_patterns.hpp"
#include "scene/light_defaults.hpp"
#include "scene/mesh_build.hpp"
#include "scene/shapes.hpp"

#include <airlight/error.hpp>
#include <airlight/scene.hpp>
#include <algorithm>
#include <array>
#include <functional>
#include <glm/geometric.hpp>
#include <map>
#include <memory>
#include <optional>

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

// `light` projecting `gobo`, its light map (Dobashi et al. 2000, §4).
Light with_gobo(Light light, std::shared_ptr<const Image> gobo) {
  light.gobo = std::move(gobo);
  return light;
}

void add_box(Scene& s, const glm::vec3& min, const glm::vec3& max, Color albedo,
             const std::string& name) {
  s.meshes.push_back(place(make_box(min, max), albedo, name));
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

// An axis-aligned region of space: a room's inside, a window opening.
struct Extent {
  glm::vec3 min, max;
};

std::array<glm::vec3, 8> corners(const Extent& e) {
  std::array<glm::vec3, 8> c;
  for (int k = 0; k < 8; ++k)
    c[k] = {(k & 1) ? e.max.x : e.min.x, (k & 2) ? e.max.y : e.min.y, (k & 4) ? e.max.z : e.min.z};
  return c;
}

// The beam of the directional light `sun` through `opening` (scene.hpp: Beam).
// Its rectangle lies upstream of the whole opening, `margin` clear of it;
// across the light it covers the opening's projection along the light with
// `margin` to spare; it reaches past every corner of `room`. The rectangle's
// axes are the gobo frame of docs/design.md §1 (optics::gobo_frame, out of this layer's
// reach): right = normalize(direction × gobo_up), up = right × direction.
Beam beam_through(const Light& sun, const Extent& opening, const Extent& room, float margin) {
  const glm::vec3 d = sun.direction, centre = 0.5f * (opening.min + opening.max);
  const glm::vec3 right = glm::normalize(glm::cross(d, sun.gobo_up)), up = glm::cross(right, d);
  float upstream = 0.0f;
  glm::vec2 half(0.0f);
  for (const glm::vec3& c : corners(opening)) {
    upstream = std::max(upstream, glm::dot(centre - c, d));
    half = glm::max(half, glm::abs(glm::vec2(glm::dot(c - centre, right), glm::dot(c - centre, up))));
  }
  Beam beam;
  beam.origin = centre - (upstream + margin) * d;
  beam.size = 2.0f * (half + margin);
  for (const glm::vec3& c : corners(room))
    beam.length = std::max(beam.length, glm::dot(c - beam.origin, d) + margin);
  return beam;
}

// A closed room around `inside`, of slabs `wall` thick, with `window` (an
// opening through the wall at z = inside.min.z), if any, left open: that wall
// is then built from the four boxes around the opening.
void add_room(Scene& s, const Extent& inside, const std::optional<Extent>& window, float wall, Color albedo) {
  const glm::vec3 lo = inside.min, hi = inside.max, w(wall);
  auto slab = [&](const glm::vec3& min, const glm::vec3& max, const char* name) {
    add_box(s, min, max, albedo, name);
  };
  slab(lo - w, {hi.x + wall, lo.y, hi.z + wall}, "floor");
  slab({lo.x - wall, hi.y, lo.z - wall}, hi + w, "ceiling");
  slab({lo.x - wall, lo.y, lo.z}, {lo.x, hi.y, hi.z}, "left wall");
  slab({hi.x, lo.y, lo.z}, {hi.x + wall, hi.y, hi.z}, "right wall");
  slab({lo.x - wall, lo.y, hi.z}, {hi.x + wall, hi.y, hi.z + wall}, "front wall");
  const float back = lo.z - wall;
  if (!window) return slab({lo.x - wall, lo.y, back}, {hi.x + wall, hi.y, lo.z}, "back wall");
  const glm::vec2 wx(window->min.x, window->max.x), wy(window->min.y, window->max.y);
  slab({lo.x - wall, lo.y, back}, {hi.x + wall, wy[0], lo.z}, "wall below window");
  slab({lo.x - wall, wy[1], back}, {hi.x + wall, hi.y, lo.z}, "wall above window");
  slab({lo.x - wall, wy[0], back}, {wx[0], wy[1], lo.z}, "wall left of window");
  slab({wx[1], wy[0], back}, {hi.x + wall, wy[1], lo.z}, "wall right of window");
}

// A table standing on y = 0: a top 5 cm thick on four legs.
void add_table(Scene& s, const glm::vec3& centre_of_top, glm::vec2 size, Color albedo) {
  const glm::vec3 c = centre_of_top, half(0.5f * size.x, 0.0f, 0.5f * size.y), thick(0.0f, 0.05f, 0.0f);
  add_box(s, c - half - thick, c + half, albedo, "table top");
  const float leg = 0.06f, inset = 0.08f;  // half-width of a leg, its inset from the top's edge
  for (const float sx : {-1.0f, 1.0f})
    for (const float sz : {-1.0f, 1.0f}) {
      const glm::vec3 foot(c.x + sx * (half.x - inset), 0.0f, c.z + sz * (half.z - inset));
      const glm::vec3 top = foot + glm::vec3(0.0f, c.y - thick.y, 0.0f);
      add_box(s, foot - glm::vec3(leg, 0.0f, leg), top + glm::vec3(leg, 0.0f, leg), albedo, "table leg");
    }
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
// other scenes (top of this file) without burning out the lit floor; an
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
  add_room(s, inside, window, wall, Color(0.32f, 0.3f, 0.27f));  // dark stone
  add_table(s, {0.1f, 0.75f, -1.3f}, {1.2f, 0.7f}, Color(0.45f, 0.3f, 0.2f));
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

// One column of the hall: a square plinth, a round shaft, a square capital.
void add_column(Scene& s, glm::vec2 at, float height, int segments, Color albedo) {
  const glm::vec3 foot(at.x, 0.0f, at.y);
  const float plinth = 0.3f, half = 0.45f, radius = 0.35f;  // the blocks' height and half-width
  add_box(s, foot - glm::vec3(half, 0.0f, half), foot + glm::vec3(half, plinth, half), albedo, "plinth");
  s.meshes.push_back(place(make_cylinder(foot + glm::vec3(0.0f, plinth, 0.0f), radius, height - 2.0f * plinth,
                                         segments),
                           albedo, "column"));
  const glm::vec3 top = foot + glm::vec3(0.0f, height, 0.0f);
  add_box(s, top - glm::vec3(half, plinth, half), top + glm::vec3(half, 0.0f, half), albedo, "capital");
}

// Tóth and Umenhoffer 2009, §5: "The scene consists of 66000 triangles and is
// illuminated by a point light" (their Fig. 3, which did not survive: this
// hall is a stand-in to that count and light). A closed stone hall, its nave
// between two arcades of eight
// columns carrying round arches and a beam, a teapot on a pedestal as the
// statue, and one point light in the left aisle at the far end: its light
// crosses the nave through the arcade toward the camera at the near end, in
// shafts between the columns' shadows. 66 308 triangles, 50 400 of them the
// statue's (builtin_scenes_test.cpp holds the count within 60k–72k).
Scene toth_hall() {
  Scene s;
  s.name = "toth_hall";
  s.camera.position = {0.6f, 1.7f, 7.0f};
  s.camera.look_at = {0.0f, 2.5f, -8.0f};
  s.camera.fov_y_deg = 60.0f;
  s.medium.sigma_s = Color(0.08f);
  s.medium.sigma_a = Color(0.01f);
  s.medium.phase = single_lobe(PhaseType::henyey_greenstein, 0.3f);
  s.ambient = Color(0.03f);
  const Color stone(0.45f, 0.42f, 0.38f);
  add_room(s, {{-8.0f, 0.0f, -17.0f}, {8.0f, 8.0f, 7.5f}}, std::nullopt, 0.3f, stone);
  // The arcades' x, the first column's z, the column spacing, the capitals' top.
  const float row = 3.0f, first = -15.0f, bay = 2.5f, height = 4.6f;
  for (const float x : {-row, row}) {
    for (int i = 0; i < 8; ++i) add_column(s, {x, first + bay * i}, height, 128, stone);
    for (int i = 0; i < 7; ++i) {  // from capital to capital, turned to span along the row
      Transform t;
      t.translate = {x, height, first + bay * (i + 0.5f)};
      t.rotate_deg = {0.0f, 90.0f, 0.0f};
      const float inner = 0.5f * bay - 0.45f, outer = 0.5f * bay;  // from the capitals' edges to their centres
      s.meshes.push_back(place(make_arch(glm::vec3(0.0f), inner, outer, 0.6f, 64), t, stone, "arch"));
    }
    const float crown = height + 0.5f * bay;
    add_box(s, {x - 0.3f, crown, first - 0.45f}, {x + 0.3f, crown + 0.5f, first + 7.0f * bay + 0.45f}, stone,
            "beam");
  }
  add_box(s, {-0.6f, 0.0f, -6.6f}, {0.6f, 1.2f, -5.4f}, stone, "pedestal");
  Transform t;
  t.translate = {0.0f, 1.2f, -6.0f};
  t.rotate_deg = {0.0f, 30.0f, 0.0f};
  t.scale = 1.4f;
  s.meshes.push_back(place(make_teapot(28), t, Color(0.7f, 0.65f, 0.55f), "statue"));
  Light point;
  point.type = LightType::point;
  point.position = {-5.5f, 3.0f, -12.0f};
  point.intensity = Color(2000.0f, 1800.0f, 1500.0f);
  s.lights.push_back(point);
  return s;
}

struct Builtin {
  std::function<Scene()> make;
  const char* description;
};

const std::map<std::string, Builtin>& builtins() {
  static const std::map<std::string, Builtin> scenes = {
      {"teapot_spot", {teapot_spot, "Dobashi 2000 Fig. 7a: a teapot on a pedestal clipping one spot's shaft"}},
      {"biri_sphere", {biri_sphere, "Biri 2006 §6: a sphere (32-edge silhouette) beyond a spot, its shadow cutting the beam"}},
      {"biri_pens", {biri_pens, "Biri 2006 Fig. 7a: two crossing pens under a spot, their shadow volumes overlapping"}},
      {"biri_media", {biri_media, "Biri 2006 Fig. 7b: a box under a spot inside red, green and blue bounded media"}},
      {"nilsson_toplight", {nilsson_toplight, "Nilsson 2008 §6 Toplight: a spot from above, orthogonal to the view, over simple objects, simplified light model"}},
      {"nilsson_parallel", {nilsson_parallel, "Nilsson 2008 §6 Parallel: a directional beam nearly along the view through bars, over a box and a sphere"}},
      {"nilsson_multiple", {nilsson_multiple, "Nilsson 2008 §6 Multiple: 25 boxes and spheres in a grid under a spot from above"}},
      {"stage", {stage, "Dobashi 2000 Fig. 7b: five coloured stage spots, some with gobos, seen from the audience, lamps in view"}},
      {"stained_glass", {stained_glass, "Dobashi 2000 Fig. 8b: a sun beam through a stained-glass window into a dusty room"}},
      {"three_lights", {three_lights, "a point light in a cage of pillars, a spot on a sphere and a low sun"}},
      {"toth_hall", {toth_hall, "Tóth 2009 §5: a hall of 66k triangles (arcades, a teapot statue) lit by one point light in fog"}}};
  return scenes;
}

// The entry of `name`; an unknown name is an error of the --builtin option, where the user
// typed it.
const Builtin& builtin(const std::string& name) {
  const auto it = builtins().find(name);
  if (it == builtins().end()) {
    std::string known;
    for (const auto& entry : builtins()) known += (known.empty() ? "" : ", ") + entry.first;
    throw InputError("--builtin", name, "unknown built-in scene (known: " + known + ")");
  }
  return it->second;
}

}  // namespace

Scene builtin_scene(const std::string& name) { return builtin(name).make(); }

std::string builtin_scene_description(const std::string& name) { return builtin(name).description; }

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : builtins()) names.push_back(entry.first);
  return names;
}

}  // namespace airlight
