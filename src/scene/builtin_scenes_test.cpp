#include "scene/test_support.hpp"

#include <airlight/scene.hpp>
#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>
#include <iterator>
#include <limits>
#include <optional>

namespace airlight {
namespace {

using scene_test::closed_after_welding;
using scene_test::finite;
using scene_test::throws_input_error;
using scene_test::well_formed;

bool unit(const glm::vec3& v) { return std::fabs(glm::length(v) - 1.0f) < 1e-5f; }

void expect_valid_light(const Light& light) {
  EXPECT_TRUE(finite(light.position) && finite(light.intensity) && finite(light.irradiance));
  EXPECT_TRUE(unit(light.direction));
  EXPECT_TRUE(unit(light.gobo_up));
  if (light.type == LightType::spot) {  // only a spot's gobo is oriented by gobo_up
    EXPECT_GT(glm::length(glm::cross(light.direction, light.gobo_up)), 1e-3f);
  }
  EXPECT_GT(light.cone_deg, 0.0f);
  EXPECT_LE(light.cone_deg, 180.0f);
  EXPECT_GE(light.edge_deg, 0.0f);
  EXPECT_LE(light.edge_deg, light.cone_deg);
  EXPECT_GT(glm::length(light.intensity + light.irradiance), 0.0f) << "a light that gives no light";
}

TEST(BuiltinScenes, EveryBuiltinLoadsWithValidData) {
  const auto names = builtin_scene_names();
  ASSERT_GE(names.size(), 3u);
  for (const std::string& name : names) {
    SCOPED_TRACE(name);
    const Scene scene = builtin_scene(name);
    EXPECT_EQ(scene.name, name);
    EXPECT_TRUE(scene.source.empty());
    EXPECT_GT(glm::length(scene.camera.look_at - scene.camera.position), 0.0f);
    EXPECT_GT(glm::length(scene.medium.sigma_s), 0.0f) << "a light-shaft scene without fog";
    ASSERT_FALSE(scene.lights.empty());
    for (const Light& light : scene.lights) expect_valid_light(light);
    ASSERT_FALSE(scene.meshes.empty());
    for (const Mesh& mesh : scene.meshes) {
      EXPECT_TRUE(well_formed(mesh));
      EXPECT_TRUE(closed_after_welding(mesh));  // shadow volumes count on it (Biri §5.1.1)
    }
  }
}

TEST(BuiltinScenes, IncludeTheDocumentsScenes) {
  const auto names = builtin_scene_names();
  for (const char* name : {"teapot_spot", "stage", "stained_glass", "biri_sphere", "biri_pens", "biri_media",
                           "nilsson_toplight", "nilsson_parallel", "nilsson_multiple", "toth_hall"})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

TEST(BuiltinScenes, EachHasADescription) {
  for (const std::string& name : builtin_scene_names()) EXPECT_GT(builtin_scene_description(name).size(), 20u) << name;
  EXPECT_TRUE(throws_input_error([] { builtin_scene_description("nope"); }, "builtin_scene_description", "nope"));
}

// Biri Fig. 7b: three bounded media of their own colour, each scattering one
// channel most.
TEST(BuiltinScenes, BiriMediaHasRedGreenAndBlueVolumes) {
  const Scene scene = builtin_scene("biri_media");
  ASSERT_EQ(scene.volumes.size(), 3u);
  for (int c = 0; c < 3; ++c) {
    const Color s = scene.volumes[c].sigma_s;
    EXPECT_GT(s[c], 5.0f * s[(c + 1) % 3]) << c;
    EXPECT_GT(s[c], 5.0f * s[(c + 2) % 3]) << c;
  }
}

TEST(BuiltinScenes, ToplightUsesNilssonsSimplifiedModel) {
  const Scene scene = builtin_scene("nilsson_toplight");
  EXPECT_EQ(scene.light_model.type, LightModelType::simplified);
  EXPECT_EQ(scene.lights[0].direction, glm::vec3(0, -1, 0));
}

// ---- geometry the scene-specific checks share -------------------------------

struct Bounds {
  glm::vec3 min{std::numeric_limits<float>::infinity()}, max{-std::numeric_limits<float>::infinity()};
  bool contains(const glm::vec3& p) const {
    return glm::all(glm::greaterThan(p, min)) && glm::all(glm::lessThan(p, max));
  }
};

// The bounds of the meshes called `name` (the built-ins name their parts).
std::optional<Bounds> bounds_of(const Scene& scene, const std::string& name) {
  std::optional<Bounds> b;
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.name != name) continue;
    if (!b) b.emplace();
    for (const glm::vec3& p : mesh.positions) {
      b->min = glm::min(b->min, p);
      b->max = glm::max(b->max, p);
    }
  }
  return b;
}

// Whether the ray from `origin` along `dir` meets any triangle (Möller–Trumbore).
bool hits_a_mesh(const Scene& scene, const glm::vec3& origin, const glm::vec3& dir) {
  for (const Mesh& mesh : scene.meshes)
    for (const glm::uvec3& t : mesh.triangles) {
      const glm::vec3 a = mesh.positions[t.x], e1 = mesh.positions[t.y] - a, e2 = mesh.positions[t.z] - a;
      const glm::vec3 p = glm::cross(dir, e2);
      const float det = glm::dot(e1, p);
      if (std::fabs(det) < 1e-12f) continue;
      const glm::vec3 s = (origin - a) / det, q = glm::cross(s, e1);
      const float u = glm::dot(s, p), v = glm::dot(dir, q);
      if (u >= -1e-6f && v >= -1e-6f && u + v <= 1.0f + 1e-6f && glm::dot(e2, q) > 0.0f) return true;
    }
  return false;
}

// Direction k of n spread evenly over the sphere (a Fibonacci lattice).
glm::vec3 sphere_direction(int k, int n) {
  const float y = 1.0f - 2.0f * (k + 0.5f) / n, r = std::sqrt(1.0f - y * y);
  const float phi = k * glm::pi<float>() * (3.0f - std::sqrt(5.0f));
  return {r * std::cos(phi), y, r * std::sin(phi)};
}

// Whether `p` projects into the image of `camera` at width:height `aspect`.
bool in_view(const Camera& camera, float aspect, const glm::vec3& p) {
  const glm::vec3 forward = glm::normalize(camera.look_at - camera.position);
  const glm::vec3 right = glm::normalize(glm::cross(forward, camera.up)), up = glm::cross(right, forward);
  const glm::vec3 q = p - camera.position;
  const float depth = glm::dot(q, forward), t = std::tan(glm::radians(0.5f * camera.fov_y_deg));
  return depth > camera.near && std::fabs(glm::dot(q, up)) < t * depth &&
         std::fabs(glm::dot(q, right)) < aspect * t * depth;
}

// The darkest and brightest channel values of an image.
glm::vec2 value_range(const Image& image) {
  glm::vec2 range(1.0f, 0.0f);
  for (const glm::vec3& p : image.pixels) {
    range.x = std::min({range.x, p.r, p.g, p.b});
    range.y = std::max({range.y, p.r, p.g, p.b});
  }
  return range;
}

// ---- stage (Dobashi et al. 2000, Fig. 7b) -----------------------------------

TEST(BuiltinScenes, StageHasFiveSpotsTwoOrMoreThrowingDotsOnBlack) {
  const Scene scene = builtin_scene("stage");
  ASSERT_EQ(scene.lights.size(), 5u);
  int gobos = 0;
  for (const Light& light : scene.lights) {
    EXPECT_EQ(light.type, LightType::spot);
    EXPECT_GE(light.cone_deg, 12.0f);
    EXPECT_LE(light.cone_deg, 25.0f);
    if (!light.gobo) continue;
    ++gobos;
    const glm::vec2 range = value_range(*light.gobo);
    EXPECT_LT(range.x, 0.05f) << "dark texels between the dots";
    EXPECT_GT(range.y, 0.95f) << "bright texels in the dots";
  }
  EXPECT_GE(gobos, 2);
}

// Each spot's cone, its axis and eight rays along its rim, lands on the stage's
// deck, and the camera sees every spot and where its axis lands.
TEST(BuiltinScenes, EveryStageSpotLandsOnTheDeckInView) {
  const Scene scene = builtin_scene("stage");
  const auto deck = bounds_of(scene, "stage floor");
  ASSERT_TRUE(deck);
  for (const Light& light : scene.lights) {
    const glm::vec3 a = light.direction, e1 = glm::normalize(glm::cross(a, glm::vec3(1, 0, 0)));
    const glm::vec3 e2 = glm::cross(a, e1);
    const float cone = glm::radians(light.cone_deg);
    for (int k = -1; k < 8; ++k) {  // -1: the axis
      const float phi = glm::quarter_pi<float>() * k;
      const glm::vec3 rim = std::cos(phi) * e1 + std::sin(phi) * e2;
      const glm::vec3 dir = k < 0 ? a : std::cos(cone) * a + std::sin(cone) * rim;
      ASSERT_LT(dir.y, 0.0f);
      const glm::vec3 hit = light.position + dir * ((deck->max.y - light.position.y) / dir.y);
      EXPECT_TRUE(hit.x > deck->min.x && hit.x < deck->max.x && hit.z > deck->min.z && hit.z < deck->max.z)
          << "spot at x = " << light.position.x << ", ray " << k << " lands at " << hit.x << ", " << hit.z;
      if (k < 0) {
        EXPECT_TRUE(in_view(scene.camera, 4.0f / 3.0f, hit));
      }
    }
    EXPECT_TRUE(in_view(scene.camera, 4.0f / 3.0f, light.position));
  }
}

// ---- stained_glass (Dobashi et al. 2000, Fig. 8b) ---------------------------

// The room's inside and its window opening, from the named slabs around them.
struct Room {
  Bounds inside, window;
};

Room room_of(const Scene& scene) {
  auto part = [&](const char* name) {
    const auto b = bounds_of(scene, name);
    EXPECT_TRUE(b) << name;
    return b.value_or(Bounds{});
  };
  const Bounds below = part("wall below window"), above = part("wall above window");
  const Bounds left = part("wall left of window"), right = part("wall right of window");
  return {{{part("left wall").max.x, part("floor").max.y, below.max.z},
           {part("right wall").min.x, part("ceiling").min.y, part("front wall").min.z}},
          {{left.max.x, below.max.y, left.min.z}, {right.min.x, above.min.y, left.max.z}}};
}

std::array<glm::vec3, 8> corners(const Bounds& b) {
  std::array<glm::vec3, 8> c;
  for (int k = 0; k < 8; ++k)
    c[k] = {(k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y, (k & 4) ? b.max.z : b.min.z};
  return c;
}

TEST(BuiltinScenes, StainedGlassSunIsAnUprightBeamWithAGobo) {
  const Scene scene = builtin_scene("stained_glass");
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& sun = scene.lights[0];
  EXPECT_EQ(sun.type, LightType::directional);
  ASSERT_TRUE(sun.beam);
  ASSERT_TRUE(sun.gobo);
  const glm::vec2 range = value_range(*sun.gobo);
  EXPECT_LT(range.x, 0.05f) << "lead";
  EXPECT_GT(range.y, 0.6f) << "glass";
  EXPECT_LT(sun.direction.y, -0.3f) << "the sun slants down into the room";
  // The frame of the beam's rectangle (scene.hpp: Beam) exists and its up,
  // the gobo's top row, points to the sky.
  const glm::vec3 right = glm::cross(sun.direction, sun.gobo_up);
  ASSERT_GT(glm::length(right), 0.1f);
  EXPECT_GT(glm::cross(glm::normalize(right), sun.direction).y, 0.0f);
}

// Every corner of the window opening, projected along the light onto the
// plane of the beam's rectangle, falls inside the rectangle, upstream of the
// opening; the beam reaches past the whole room.
TEST(BuiltinScenes, StainedGlassBeamCoversTheWindowAndReachesThroughTheRoom) {
  const Scene scene = builtin_scene("stained_glass");
  const Light& sun = scene.lights.at(0);
  ASSERT_TRUE(sun.beam);
  const Beam& beam = *sun.beam;
  const glm::vec3 d = sun.direction, right = glm::normalize(glm::cross(d, sun.gobo_up));
  const glm::vec3 up = glm::cross(right, d);
  const Room room = room_of(scene);
  for (const glm::vec3& corner : corners(room.window)) {
    const glm::vec3 q = corner - beam.origin;
    EXPECT_GT(glm::dot(q, d), 0.0f) << "the rectangle lies outside, upstream of the window";
    EXPECT_LT(std::fabs(glm::dot(q, right)), 0.5f * beam.size.x);
    EXPECT_LT(std::fabs(glm::dot(q, up)), 0.5f * beam.size.y);
  }
  for (const glm::vec3& corner : corners(room.inside))
    EXPECT_LT(glm::dot(corner - beam.origin, d), beam.length);
}

// Rays from the camera and from points near the room's corners meet a surface
// in every direction except through the window: the room is closed but for it,
// and the camera is inside.
TEST(BuiltinScenes, StainedGlassRoomIsClosedButForTheWindow) {
  const Scene scene = builtin_scene("stained_glass");
  const Room room = room_of(scene);
  ASSERT_TRUE(room.inside.contains(scene.camera.position));
  std::vector<glm::vec3> origins{scene.camera.position};
  const glm::vec3 centre = 0.5f * (room.inside.min + room.inside.max);
  for (const glm::vec3& corner : corners(room.inside))
    origins.push_back(glm::mix(corner, centre, 0.05f));
  int escaped = 0;
  for (const glm::vec3& origin : origins)
    for (int k = 0; k < 4000; ++k) {
      const glm::vec3 dir = sphere_direction(k, 4000);
      if (hits_a_mesh(scene, origin, dir)) continue;
      ++escaped;
      // It leaves through the opening: it crosses the wall's inner face there.
      ASSERT_LT(dir.z, 0.0f);
      const glm::vec3 at = origin + dir * ((room.window.max.z - origin.z) / dir.z);
      EXPECT_TRUE(at.x > room.window.min.x && at.x < room.window.max.x && at.y > room.window.min.y &&
                  at.y < room.window.max.y)
          << "a ray from " << origin.x << ", " << origin.y << ", " << origin.z << " escapes at " << at.x
          << ", " << at.y;
    }
  EXPECT_GT(escaped, 0) << "the window is open";
}

// ---- toth_hall (Tóth and Umenhoffer 2009, §5) --------------------------------

size_t triangle_count(const Scene& scene) {
  size_t n = 0;
  for (const Mesh& mesh : scene.meshes) n += mesh.triangles.size();
  return n;
}

// "The scene consists of 66000 triangles and is illuminated by a point light."
TEST(BuiltinScenes, TothHallHasAbout66000TrianglesAndOnePointLight) {
  const Scene scene = builtin_scene("toth_hall");
  const size_t n = triangle_count(scene);
  RecordProperty("triangles", std::to_string(n));
  EXPECT_GE(n, 60000u);
  EXPECT_LE(n, 72000u);
  ASSERT_EQ(scene.lights.size(), 1u);
  EXPECT_EQ(scene.lights[0].type, LightType::point);
  EXPECT_EQ(std::count_if(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return m.name == "column"; }),
            16);
}

// The light and the camera stand inside the hall's walls and outside the bounds
// of every object in it, and every ray from them meets the walls: the hall is closed.
TEST(BuiltinScenes, TothHallEnclosesTheLightAndTheCameraOutsideEveryObject) {
  const Scene scene = builtin_scene("toth_hall");
  const auto floor = bounds_of(scene, "floor"), ceiling = bounds_of(scene, "ceiling");
  const auto left = bounds_of(scene, "left wall"), right = bounds_of(scene, "right wall");
  const auto front = bounds_of(scene, "front wall"), back = bounds_of(scene, "back wall");
  ASSERT_TRUE(floor && ceiling && left && right && front && back);
  const Bounds inside{{left->max.x, floor->max.y, back->max.z}, {right->min.x, ceiling->min.y, front->min.z}};
  const auto is_wall = [](const Mesh& m) {
    return m.name.find("wall") != std::string::npos || m.name == "floor" || m.name == "ceiling";
  };
  Scene walls;
  std::copy_if(scene.meshes.begin(), scene.meshes.end(), std::back_inserter(walls.meshes), is_wall);
  ASSERT_EQ(walls.meshes.size(), 6u);
  for (const glm::vec3& p : {scene.lights.at(0).position, scene.camera.position}) {
    EXPECT_TRUE(inside.contains(p));
    for (const Mesh& mesh : scene.meshes) {
      if (is_wall(mesh)) continue;
      Bounds b;
      for (const glm::vec3& q : mesh.positions) {
        b.min = glm::min(b.min, q);
        b.max = glm::max(b.max, q);
      }
      EXPECT_FALSE(b.contains(p)) << mesh.name;
    }
    for (int k = 0; k < 2000; ++k) EXPECT_TRUE(hits_a_mesh(walls, p, sphere_direction(k, 2000))) << k;
  }
}

// Named as the option the user typed it in, listing the names there are.
TEST(BuiltinScenes, UnknownNameIsAnInputErrorListingTheKnown) {
  EXPECT_TRUE(throws_input_error([] { builtin_scene("no_such_scene", "--builtin"); }, "--builtin", "no_such_scene",
                                 "unknown built-in scene (known: biri_media, biri_pens, biri_sphere, "
                                 "nilsson_multiple, nilsson_parallel, nilsson_toplight, stage, stained_glass, "
                                 "teapot_spot, three_lights, toth_hall)"));
}

}  // namespace
}  // namespace airlight
