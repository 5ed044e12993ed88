// glTF scenes (docs/scene-format.md "glTF scenes"): unit conversions, node transforms,
// equivalence with a JSON scene, the fog sources, and each malformed element's message.
#include "core/warning.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/shapes.hpp"
#include "scene/test_support.hpp"

#include <airlight/scene.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#define GLM_ENABLE_EXPERIMENTAL
#include <glm/gtx/quaternion.hpp>  // glm::rotation
#include <gtest/gtest.h>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

namespace airlight {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using scene_test::throws_input_error;
using scene_test::well_formed;
using scene_mesh::make_box;

fs::path work_dir() {
  const fs::path dir = fs::path(::testing::TempDir()) / "airlight_gltf_scene";
  fs::create_directories(dir);
  return dir;
}

void expect_vec(const glm::vec3& actual, const glm::vec3& expected, float tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

// A glTF document written as name.gltf with its buffer in name.bin.
struct Gltf {
  Json json = {{"asset", {{"version", "2.0"}}}, {"scene", 0}, {"scenes", {{{"nodes", Json::array()}}}},
               {"nodes", Json::array()}, {"meshes", Json::array()}, {"accessors", Json::array()},
               {"bufferViews", Json::array()}};
  std::string bin;

  int accessor(const void* data, size_t bytes, size_t count, const char* type, int component_type) {
    json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}});
    bin.append(static_cast<const char*>(data), bytes);
    while (bin.size() % 4) bin.push_back('\0');
    json["accessors"].push_back({{"bufferView", json["bufferViews"].size() - 1},
                                 {"componentType", component_type}, {"count", count}, {"type", type}});
    return int(json["accessors"].size() - 1);
  }
  int vec3s(const std::vector<glm::vec3>& v) { return accessor(v.data(), 12 * v.size(), v.size(), "VEC3", 5126); }
  int indices(const std::vector<uint16_t>& i) { return accessor(i.data(), 2 * i.size(), i.size(), "SCALAR", 5123); }

  // A mesh of the given triangles, optionally with normals; returns the mesh's index.
  int mesh(const std::vector<glm::vec3>& positions, const std::vector<uint16_t>& tris,
           const std::vector<glm::vec3>& normals = {}) {
    Json attributes = {{"POSITION", vec3s(positions)}};
    if (!normals.empty()) attributes["NORMAL"] = vec3s(normals);
    json["meshes"].push_back({{"primitives", {{{"attributes", attributes}, {"indices", indices(tris)}}}}});
    return int(json["meshes"].size() - 1);
  }
  int node(Json node, bool root = true) {
    json["nodes"].push_back(std::move(node));
    const int n = int(json["nodes"].size() - 1);
    if (root) json["scenes"][0]["nodes"].push_back(n);
    return n;
  }
  int light(Json light) {
    Json& lights = json["extensions"]["KHR_lights_punctual"]["lights"];
    lights.push_back(std::move(light));
    return int(lights.size() - 1);
  }
  fs::path write(const std::string& name) {
    const fs::path dir = work_dir();
    if (!bin.empty()) {
      json["buffers"] = {{{"uri", name + ".bin"}, {"byteLength", bin.size()}}};
      std::ofstream(dir / (name + ".bin"), std::ios::binary) << bin;
    }
    std::ofstream(dir / (name + ".gltf")) << json.dump(1);
    return dir / (name + ".gltf");
  }
};

const std::vector<glm::vec3> triangle = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};

Json quaternion(const glm::dquat& q) { return {q.x, q.y, q.z, q.w}; }

// ---- conversions ----

TEST(GltfScene, PhotometricUnitsDivideBy683AndTheColorMultiplies) {
  Gltf g;
  const int point = g.light({{"type", "point"}, {"intensity", 683.0 * 4}, {"color", {1, 0.5, 0.25}}});
  const int sun = g.light({{"type", "directional"}, {"intensity", 683.0 * 2}});
  g.node({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", point}}}}}});
  g.node({{"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
  const Scene s = load_scene(g.write("units"));
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, LightType::point);
  expect_vec(s.lights[0].intensity, {4, 2, 1}, 1e-6f);  // cd / 683 = W/sr
  expect_vec(s.lights[0].position, {1, 2, 3}, 0.0f);
  EXPECT_EQ(s.lights[1].type, LightType::directional);
  expect_vec(s.lights[1].irradiance, {2, 2, 2}, 1e-6f);  // lux / 683 = W/m², white by default
  expect_vec(s.lights[1].direction, {0, 0, -1}, 0.0f);   // down the node's −Z
}

// A node naming a mesh again adds its triangles again: a mesh of 700 000 (one triangle
// listed over and over) on three nodes is over the scene's limit at the third.
TEST(GltfScene, NodesNamingAMeshAgainCountTowardTheTriangleLimit) {
  Gltf g;
  std::vector<uint16_t> indices;
  for (int i = 0; i < 700000; ++i) indices.insert(indices.end(), {0, 1, 2});
  const int mesh = g.mesh(triangle, indices, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});  // with normals: quick to read
  for (int n = 0; n < 3; ++n) g.node({{"mesh", mesh}});
  const fs::path file = g.write("instanced");
  EXPECT_TRUE(throws_input_error([&] { load_scene(file); }, file.string(), "meshes[0].primitives[0]",
                                 "the scene's meshes have more than 2097152 triangles in all"));
}

// tinygltf copies the JSON by recursion: a text nested thousands deep would overflow
// the stack. 100 levels are read, 101 refused before tinygltf sees them.
TEST(GltfScene, JsonNestedDeeperThan100LevelsIsRefused) {
  const auto nested = [](int arrays) {
    return R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": []}], "extras": )" + std::string(arrays, '[') +
           std::string(arrays, ']') + "}";
  };
  const fs::path file = work_dir() / "deep.gltf";
  std::ofstream(file) << nested(99);
  EXPECT_NO_THROW(load_scene(file));
  std::ofstream(file) << nested(100);
  EXPECT_TRUE(throws_input_error([&] { load_scene(file); }, file.string(), "", "the JSON nests deeper than 100 levels"));
}

TEST(GltfScene, SpotConesMapOuterToConeAndTheirDifferenceToEdge) {
  const double deg = std::numbers::pi / 180.0;
  const scene_gltf::SpotCone cone = scene_gltf::spot_cone(17.5 * deg, 25.0 * deg);
  EXPECT_NEAR(cone.cone_deg, 25.0f, 1e-5f);
  EXPECT_NEAR(cone.edge_deg, 7.5f, 1e-5f);
  // The extension's defaults: inner 0, outer π/4: a smooth edge across the whole cone.
  Gltf g;
  const int spot = g.light({{"type", "spot"}, {"spot", Json::object()}});
  g.node({{"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}});
  const Scene s = load_scene(g.write("spot_defaults"));
  EXPECT_NEAR(s.lights[0].cone_deg, 45.0f, 1e-5f);
  EXPECT_NEAR(s.lights[0].edge_deg, 45.0f, 1e-5f);
  expect_vec(s.lights[0].intensity, glm::vec3(1.0f / 683.0f), 1e-9f);
}

// KHR_lights_punctual's recommended spot falloff ("Inner and Outer Cone Angles"): a ramp
// linear in the cosine from outer to inner, squared.
double gltf_falloff(double inner, double outer, double angle) {
  const double scale = 1.0 / std::max(0.001, std::cos(inner) - std::cos(outer));
  const double t = std::clamp((std::cos(angle) - std::cos(outer)) * scale, 0.0, 1.0);
  return t * t;
}

// airlight's edge (optics::spot_cone): a smoothstep in the angle over [cone − edge, cone].
double airlight_falloff(double inner, double outer, double angle) {
  const double t = std::clamp((outer - angle) / (outer - inner), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

double max_falloff_difference(double inner_deg, double outer_deg) {
  const double deg = std::numbers::pi / 180.0;
  double worst = 0.0;
  for (int i = 0; i <= 10000; ++i) {
    const double angle = (inner_deg + (outer_deg - inner_deg) * i / 10000.0) * deg;
    worst = std::max(worst, std::fabs(gltf_falloff(inner_deg * deg, outer_deg * deg, angle) -
                                      airlight_falloff(inner_deg * deg, outer_deg * deg, angle)));
  }
  return worst;
}

// The two falloffs agree at both ends of the edge and differ inside it: glTF's squared
// ramp falls steeply from the inner cone and levels off toward the outer one, the smoothstep
// is flat at both ends. As the edge narrows, the cosine becomes linear in the angle and the
// difference tends to max 2t²(1 − t) = 8/27 ≈ 0.296 (t = 2/3 of the way from the outer cone
// to the inner). The numbers are docs/decisions.md's "glTF scenes"; the tolerance is the
// sampling's (10⁴ steps).
TEST(GltfScene, SpotFalloffDiffersFromTheSmoothstepByAMeasuredAmount) {
  const double blender_default = max_falloff_difference(22.5 * (1 - 0.15), 22.5);  // size 45°, blend 0.15
  const double fixture = max_falloff_difference(17.5, 25.0);
  const double whole_cone = max_falloff_difference(0.0, 45.0);  // the extension's defaults
  std::printf("max |glTF - smoothstep| over the edge: Blender default %.4f, fixture %.4f, inner 0 outer 45: %.4f\n",
              blender_default, fixture, whole_cone);
  EXPECT_NEAR(blender_default, 0.2730, 1e-4);
  EXPECT_NEAR(fixture, 0.2449, 1e-4);
  EXPECT_NEAR(whole_cone, 0.0480, 1e-4);
}

// ---- transforms ----

// A hierarchy of TRS and matrix nodes places a triangle, a spot and a camera where the
// transforms, multiplied out by hand, put them.
TEST(GltfScene, NodeHierarchyComposesTranslationRotationScaleAndMatrix) {
  Gltf g;
  const int mesh = g.mesh(triangle, {0, 1, 2});
  const int spot = g.light({{"type", "spot"}, {"spot", {{"outerConeAngle", 0.5}}}});
  g.json["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 30}}}}};
  // root: translate (10, 0, 0), rotate 90° about +Y. child: scale 2. leaf: matrix translating (0, 0, 1).
  const double h = std::sqrt(0.5);
  const Json leaf = {{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1}}, {"mesh", mesh},
                     {"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}, {"camera", 0}};
  const int leaf_node = g.node(leaf, false);
  const int child = g.node({{"scale", {2, 2, 2}}, {"children", {leaf_node}}}, false);
  g.node({{"translation", {10, 0, 0}}, {"rotation", {0, h, 0, h}}, {"children", {child}}});
  const Scene s = load_scene(g.write("hierarchy"));
  // R_y(90°) maps (x, y, z) to (z, y, −x); the leaf's point p is at 10·x̂ + R(2·(p + ẑ)).
  const auto place = [](glm::vec3 p) {
    const glm::vec3 q = 2.0f * (p + glm::vec3(0, 0, 1));
    return glm::vec3(10 + q.z, q.y, -q.x);
  };
  ASSERT_EQ(s.meshes.size(), 1u);
  ASSERT_TRUE(well_formed(s.meshes[0]));
  for (size_t i = 0; i < 3; ++i) expect_vec(s.meshes[0].positions[i], place(triangle[i]), 1e-5f);
  // Flat normals (no NORMAL given): the triangle faces its local +Z, R_y(90°) of which is +X.
  for (const glm::vec3& n : s.meshes[0].normals) expect_vec(n, {1, 0, 0}, 1e-6f);
  expect_vec(s.lights[0].position, place({0, 0, 0}), 1e-5f);
  expect_vec(s.lights[0].direction, {-1, 0, 0}, 1e-6f);  // local −Z → −X
  expect_vec(s.camera.position, place({0, 0, 0}), 1e-5f);
  expect_vec(s.camera.look_at - s.camera.position, {-1, 0, 0}, 1e-5f);
  expect_vec(s.camera.up, {0, 1, 0}, 1e-6f);
  EXPECT_NEAR(s.camera.fov_y_deg, 0.5 * 180 / std::numbers::pi, 1e-4);
  EXPECT_FLOAT_EQ(s.camera.near, 0.1f);
  EXPECT_FLOAT_EQ(s.camera.far, 30.0f);
}

// A mirroring transform keeps triangles counter-clockwise about their normals (§3.7.2.1).
TEST(GltfScene, MirroredNodesKeepWindingConsistentWithNormals) {
  Gltf g;
  const Mesh box = make_box({-1, -1, -1}, {1, 1, 1});
  std::vector<uint16_t> tris;
  for (const glm::uvec3& t : box.triangles) tris.insert(tris.end(), {uint16_t(t.x), uint16_t(t.y), uint16_t(t.z)});
  g.node({{"scale", {-1, 1, 1}}, {"mesh", g.mesh(box.positions, tris, box.normals)}});
  const Scene s = load_scene(g.write("mirrored"));
  EXPECT_EQ(scene_test::misoriented_fraction(s.meshes[0]), 0.0);
  EXPECT_GT(scene_test::signed_volume(s.meshes[0]), 0.0);
}

// A zero scale hides a node's mesh (§3.5.3); a light under it has no direction.
TEST(GltfScene, ZeroScaleHidesAMeshAndLeavesALightWithoutDirection) {
  Gltf g;
  g.node({{"mesh", g.mesh(triangle, {0, 1, 2})}, {"scale", {0, 0, 0}}});
  EXPECT_TRUE(load_scene(g.write("zero_scale")).meshes.empty());
  const int sun = g.light({{"type", "directional"}});
  g.node({{"scale", {0, 0, 0}}, {"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
  const fs::path file = g.write("zero_scale_light");
  EXPECT_TRUE(throws_input_error([&] { load_scene(file); }, file.string(), "extensions.KHR_lights_punctual.lights[0]",
                                 "its node's transform has a zero scale: it has no direction"));
}

// ---- equivalence with a JSON scene ----

// The same box, spot and camera written as a scene file and as glTF load to the same model.
TEST(GltfScene, LoadsToTheSameSceneAsTheEquivalentJson) {
  const Json scene_json = {
      {"format", "airlight-scene/1"},
      {"camera", {{"position", {0, 2, 8}}, {"look_at", {0, 1, 0}}, {"fov_y_deg", 40}}},
      {"lights", {{{"type", "spot"}, {"position", {1, 5, 0}}, {"direction", {0.3, -1, 0.2}},
                   {"intensity", {100, 80, 60}}, {"cone_deg", 30}, {"edge_deg", 10}}}},
      {"objects", {{{"shape", "box"}, {"min", {-1, 0, -0.5}}, {"max", {1, 2, 0.5}}, {"translate", {0.5, 0, -1}},
                    {"rotate_deg", {0, 35, 0}}, {"scale", 1.5}, {"albedo", {0.2, 0.4, 0.6}}}}}};
  const Scene expected = parse_scene(scene_json.dump(), (work_dir() / "equivalent.json").string());

  Gltf g;
  const Mesh box = make_box({-1, 0, -0.5}, {1, 2, 0.5});
  std::vector<uint16_t> tris;
  for (const glm::uvec3& t : box.triangles) tris.insert(tris.end(), {uint16_t(t.x), uint16_t(t.y), uint16_t(t.z)});
  g.json["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.4, 0.6, 1}}}}}};
  const int mesh = g.mesh(box.positions, tris, box.normals);
  g.json["meshes"][mesh]["primitives"][0]["material"] = 0;
  const double pi = std::numbers::pi;
  g.node({{"mesh", mesh}, {"translation", {0.5, 0, -1}}, {"scale", {1.5, 1.5, 1.5}},
          {"rotation", quaternion(glm::angleAxis(35 * pi / 180, glm::dvec3(0, 1, 0)))}});
  const int spot = g.light({{"type", "spot"}, {"intensity", 683.0 * 100}, {"color", {1, 0.8, 0.6}},
                            {"spot", {{"innerConeAngle", 20 * pi / 180}, {"outerConeAngle", 30 * pi / 180}}}});
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -1, 0.2));
  g.node({{"translation", {1, 5, 0}}, {"rotation", quaternion(glm::rotation(glm::dvec3(0, 0, -1), axis))},
          {"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}});
  // Pitched about X only, so the camera's up stays in the vertical plane, as the JSON's.
  const double pitch = std::atan2(-1.0, 8.0);
  g.json["cameras"] = {
      {{"type", "perspective"}, {"perspective", {{"yfov", 40 * pi / 180}, {"znear", 0.05}, {"zfar", 50}}}}};
  g.node({{"camera", 0}, {"translation", {0, 2, 8}},
          {"rotation", quaternion(glm::angleAxis(pitch, glm::dvec3(1, 0, 0)))}});
  const Scene actual = load_scene(g.write("equivalent"));

  ASSERT_EQ(actual.meshes.size(), 1u);
  const Mesh &a = actual.meshes[0], &e = expected.meshes[0];
  ASSERT_EQ(a.positions.size(), e.positions.size());
  ASSERT_EQ(a.triangles, e.triangles);
  for (size_t i = 0; i < a.positions.size(); ++i) {
    expect_vec(a.positions[i], e.positions[i], 2e-6f);  // float rounding of ~3 m coordinates
    expect_vec(a.normals[i], e.normals[i], 1e-6f);
  }
  expect_vec(a.albedo, e.albedo, 1e-7f);
  ASSERT_EQ(actual.lights.size(), 1u);
  const Light &la = actual.lights[0], &le = expected.lights[0];
  EXPECT_EQ(la.type, le.type);
  expect_vec(la.position, le.position, 1e-6f);
  expect_vec(la.direction, le.direction, 1e-6f);
  expect_vec(la.intensity, le.intensity, 1e-4f);
  EXPECT_NEAR(la.cone_deg, le.cone_deg, 1e-5f);
  EXPECT_NEAR(la.edge_deg, le.edge_deg, 1e-5f);
  expect_vec(la.gobo_up, le.gobo_up, 0.0f);
  const Camera &ca = actual.camera, &ce = expected.camera;
  expect_vec(ca.position, ce.position, 1e-6f);
  expect_vec(glm::normalize(ca.look_at - ca.position), glm::normalize(ce.look_at - ce.position), 1e-6f);
  // Equal images need equal right vectors (camera_basis: forward × up), not equal ups.
  const glm::vec3 forward = glm::normalize(ce.look_at - ce.position);
  expect_vec(glm::normalize(glm::cross(forward, ca.up)), glm::normalize(glm::cross(forward, ce.up)), 1e-6f);
  EXPECT_NEAR(ca.fov_y_deg, ce.fov_y_deg, 1e-4f);
  EXPECT_EQ(ca.near, ce.near);
  EXPECT_EQ(ca.far, ce.far);
}

// ---- fog ----

TEST(GltfScene, FogComesFromTheSceneExtrasAirlightObject) {
  Gltf g;
  g.node({{"mesh", g.mesh(triangle, {0, 1, 2})}});
  g.json["scenes"][0]["extras"] = {
      {"other_tool", {{"anything", 1}}},
      {"airlight", {{"medium", {{"scattering", 0.1}, {"phase", {{"type", "henyey_greenstein"}, {"g", 0.5}}}}},
                    {"volumes", {{{"shape", "box"}, {"min", {0, 0, 0}}, {"max", {1, 1, 1}}, {"scattering", 0.2}}}},
                    {"light_model", {{"type", "simplified"}, {"a1", 2}}}, {"ambient", 0.03}}}};
  const Scene s = load_scene(g.write("extras"));
  expect_vec(s.medium.sigma_s, glm::vec3(0.1f), 0.0f);
  ASSERT_EQ(s.medium.phase.lobes.size(), 1u);
  EXPECT_EQ(s.medium.phase.lobes[0].type, PhaseType::henyey_greenstein);
  EXPECT_FLOAT_EQ(s.medium.phase.lobes[0].g, 0.5f);
  ASSERT_EQ(s.volumes.size(), 1u);
  expect_vec(s.volumes[0].sigma_s, glm::vec3(0.2f), 0.0f);
  EXPECT_EQ(s.light_model.type, LightModelType::simplified);
  expect_vec(s.ambient, glm::vec3(0.03f), 0.0f);
}

// No fog information: no medium, and with no camera one framing the meshes' bounding sphere.
TEST(GltfScene, WithoutFogOrCameraTheMediumIsEmptyAndTheCameraFramesTheMeshes) {
  Gltf g;
  g.node({{"mesh", g.mesh(triangle, {0, 1, 2})}, {"translation", {4, 0, 0}}});
  const Scene s = load_scene(g.write("bare"));
  expect_vec(s.medium.sigma_t(), glm::vec3(0.0f), 0.0f);
  EXPECT_TRUE(s.volumes.empty());
  const glm::vec3 centre(4.5f, 0.5f, 0.0f);
  const float radius = 0.5f * std::sqrt(2.0f);
  expect_vec(s.camera.look_at, centre, 1e-6f);
  // The sphere just fills the 45° field: distance · sin(22.5°) = radius, from the front (+Z).
  EXPECT_NEAR(glm::distance(s.camera.position, centre) * std::sin(glm::radians(22.5f)), radius, 1e-5f);
  expect_vec(glm::normalize(s.camera.position - centre), glm::normalize(glm::vec3(0, 0.5f, 1)), 1e-6f);
}

// A model 100 km across: the framing camera's far reaches past it, and its near
// rises from the default so that far/near stays within what airlight supports.
TEST(GltfScene, TheFramingCameraOfAHugeModelKeepsFarOverNearInRange) {
  Gltf g;
  g.node({{"mesh", g.mesh(triangle, {0, 1, 2})}, {"scale", {1e5, 1e5, 1e5}}});
  const Camera c = load_scene(g.write("huge")).camera;
  EXPECT_GT(c.far, 1e5f);
  EXPECT_LE(double(c.far) / double(c.near), max_far_over_near);
  EXPECT_GT(double(c.far) / double(c.near), 0.99 * max_far_over_near);  // no nearer than it must be
}

// The file loads as one mesh of `triangles` triangles, warning `warning` once.
void expect_one_mesh_and_warning(const fs::path& file, size_t triangles, const std::string& warning) {
  const CapturedWarnings warnings;
  const Scene s = load_scene(file);
  ASSERT_EQ(s.meshes.size(), 1u);
  EXPECT_EQ(s.meshes[0].triangles.size(), triangles);
  EXPECT_EQ(warnings.text(), "airlight: warning: " + file.string() + ": " + warning + "\n");
}

// Zero-area triangles are skipped with one warning per primitive that counts them, as an OBJ's,
// with normals given or not.
TEST(GltfScene, DegenerateTrianglesAreSkippedWithAWarningThatCountsThem) {
  const std::vector<glm::vec3> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<uint16_t> tris = {0, 1, 2, 0, 2, 3, 0, 0, 1, 1, 2, 2};
  for (const bool normals : {false, true}) {
    Gltf g;
    g.node({{"mesh", g.mesh(square, tris, normals ? std::vector<glm::vec3>(4, {0, 0, 1}) : std::vector<glm::vec3>{})}});
    expect_one_mesh_and_warning(g.write(normals ? "slivers_n" : "slivers"), 2,
                                "meshes[0].primitives[0]: skipped 2 degenerate triangles (zero area)");
  }
}

// A scene file with "gltf" starts from the glTF's scene; its own keys replace the glTF's, and
// its lights and objects add to the glTF's.
TEST(GltfScene, ASceneFileBesideTheGltfAddsFogLightsAndObjects) {
  Gltf g;
  g.node({{"mesh", g.mesh(triangle, {0, 1, 2})}});
  g.json["scenes"][0]["extras"] = {{"airlight", {{"medium", {{"scattering", 0.1}}}, {"ambient", 0.5}}}};
  g.write("wrapped");
  const Json wrapper = {{"format", "airlight-scene/1"},
                        {"gltf", "wrapped.gltf"},
                        {"medium", {{"scattering", 0.04}}},
                        {"camera", {{"position", {0, 1, 5}}}},
                        {"lights", {{{"type", "point"}, {"position", {0, 3, 0}}, {"intensity", 10}}}},
                        {"objects", {{{"shape", "box"}, {"min", {-1, -1, -1}}, {"max", {1, 1, 1}}}}}};
  const fs::path file = work_dir() / "wrapper.json";
  std::ofstream(file) << wrapper.dump();
  const Scene s = load_scene(file);
  EXPECT_EQ(s.name, "wrapper");
  expect_vec(s.medium.sigma_s, glm::vec3(0.04f), 0.0f);  // the JSON's
  expect_vec(s.ambient, glm::vec3(0.5f), 0.0f);          // the glTF's, the JSON giving none
  expect_vec(s.camera.position, {0, 1, 5}, 0.0f);
  ASSERT_EQ(s.meshes.size(), 2u);
  EXPECT_EQ(s.meshes[0].name, "nodes[0]");
  EXPECT_EQ(s.meshes[1].name, "objects[0] (box)");
  EXPECT_EQ(s.lights.size(), 1u);
  EXPECT_TRUE(throws_input_error([] { parse_scene(R"({"format": "airlight-scene/1", "gltf": "x.obj"})",
                                                  (work_dir() / "w.json").string()); },
                                 (work_dir() / "w.json").string(), "gltf", "must name a .gltf or .glb file"));
}

// ---- Blender's export ----

// The fixture of tests/data/gltf/make_blender_scene.py, as its script sets it up in Blender.
TEST(GltfScene, BlendersExportLoadsWithTheValuesSetInBlender) {
  const Scene s = load_scene(test::test_data() / "gltf" / "blender_shafts.glb");
  ASSERT_EQ(s.meshes.size(), 4u);
  for (const Mesh& m : s.meshes) EXPECT_TRUE(well_formed(m));
  EXPECT_EQ(s.meshes[1].name, "nodes[1] (ColumnLeft)");
  // Blender's (-1.5, 0, 1.25) under the empty at (0, 0.5, 0) turned 10° about z, then y-up.
  glm::vec3 centre(0.0f);
  for (const glm::vec3& p : s.meshes[1].positions) centre += p / float(s.meshes[1].positions.size());
  const float c = std::cos(glm::radians(10.0f)), sn = std::sin(glm::radians(10.0f));
  expect_vec(centre, {-1.5f * c, 1.25f, -(0.5f - 1.5f * sn)}, 1e-5f);
  expect_vec(s.meshes[0].albedo, glm::vec3(0.6f), 1e-7f);
  ASSERT_EQ(s.lights.size(), 2u);
  const Light &spot = s.lights[0], &sun = s.lights[1];
  EXPECT_EQ(spot.type, LightType::spot);
  // 2500 W: Blender's exporter writes 2500 / (4π) · 683 cd; back at 683 lm/W, 2500 / (4π) W/sr.
  expect_vec(spot.intensity, glm::vec3(float(2500 / (4 * std::numbers::pi))), 1e-3f);
  EXPECT_NEAR(spot.cone_deg, 25.0f, 1e-4f);
  EXPECT_NEAR(spot.edge_deg, 7.5f, 1e-4f);
  expect_vec(spot.position, {0, 5, -3.5f}, 1e-6f);
  expect_vec(spot.direction, glm::normalize(glm::vec3(0, -5, 3.5f)), 1e-6f);  // aimed at the origin
  EXPECT_EQ(sun.type, LightType::directional);
  expect_vec(sun.irradiance, {0.3f, 0.27f, 0.24f}, 1e-6f);
  expect_vec(s.camera.position, {0, 3, 8}, 1e-6f);
  EXPECT_NEAR(s.camera.fov_y_deg, 50.0f, 1e-4f);
  EXPECT_FLOAT_EQ(s.camera.far, 40.0f);
  expect_vec(s.medium.sigma_s, glm::vec3(0.08f), 0.0f);
  expect_vec(s.medium.sigma_a, glm::vec3(0.01f), 0.0f);
  expect_vec(s.ambient, glm::vec3(0.02f), 0.0f);
}

// §3.7.2.1: a strip's and a fan's triangles are the list's, each wound as the
// specification orders them (so every face keeps the normal's side).
TEST(GltfScene, TriangleStripsAndFansReadAsTriangles) {
  const std::vector<glm::vec3> square = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  const auto load = [&](int mode, const std::vector<uint16_t>& indices) {
    Gltf g;
    g.node({{"mesh", g.mesh(square, indices)}});
    g.json["meshes"][0]["primitives"][0]["mode"] = mode;
    return load_scene(g.write("mode" + std::to_string(mode)));
  };
  for (const Scene& s : {load(5, {0, 1, 2, 3}), load(6, {1, 3, 2, 0})}) {
    ASSERT_EQ(s.meshes.size(), 1u);
    const Mesh& m = s.meshes[0];
    ASSERT_EQ(m.triangles.size(), 2u);
    for (const glm::uvec3& t : m.triangles) {  // counter-clockwise seen from +z, as the list's
      const glm::vec3 n = glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]);
      EXPECT_GT(n.z, 0.0f);
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);  // each half of the unit square
    }
  }
}

// Points and lines beside triangles: left out, one warning counting them.
TEST(GltfScene, PointsAndLinesAreSkippedWithAWarningThatCountsThem) {
  Gltf g;
  g.node({{"mesh", g.mesh(triangle, {0, 1, 2})}});
  Json lines = g.json["meshes"][0]["primitives"][0];
  lines["mode"] = 1;
  Json points = lines;
  points["mode"] = 0;
  g.json["meshes"][0]["primitives"].push_back(lines);
  g.json["meshes"][0]["primitives"].push_back(points);
  expect_one_mesh_and_warning(g.write("points_and_lines"), 1,
                              "skipped 2 primitives of points or lines (airlight renders triangles)");
}

// Several scenes: the default one, or the first, with a note saying which.
TEST(GltfScene, OfSeveralScenesTheDefaultOrTheFirstIsRendered) {
  for (const bool named : {true, false}) {
    Gltf g;
    g.node({{"mesh", g.mesh(triangle, {0, 1, 2})}});
    g.json["scenes"].push_back({{"nodes", Json::array()}});  // scenes[1]: empty
    if (named) g.json["scene"] = 1;
    else g.json.erase("scene");
    const fs::path file = g.write(named ? "default_scene" : "first_scene");
    const CapturedWarnings warnings;
    const Scene s = load_scene(file);
    EXPECT_EQ(s.meshes.size(), named ? 0u : 1u);
    EXPECT_EQ(warnings.text(), "airlight: warning: " + file.string() + ": has 2 scenes: rendering " +
                                  (named ? "scenes[1], its default" : "scenes[0], the first (the file names no default)") +
                                  "\n");
  }
}

// ---- malformed files ----

struct Malformed {
  const char* name;
  void (*edit)(Gltf&);
  const char* key;
  const char* message;
};

void PrintTo(const Malformed& m, std::ostream* os) { *os << m.name; }

class GltfMalformed : public testing::TestWithParam<Malformed> {};

TEST_P(GltfMalformed, FailsNamingTheFileAndTheElement) {
  const Malformed& m = GetParam();
  Gltf g;
  g.node({{"mesh", g.mesh(triangle, {0, 1, 2})}});
  m.edit(g);
  const fs::path file = g.write(m.name);
  EXPECT_TRUE(throws_input_error([&] { load_scene(file); }, file.string(), m.key, m.message));
}

INSTANTIATE_TEST_SUITE_P(
    Elements, GltfMalformed,
    testing::Values(
        Malformed{"lines", [](Gltf& g) { g.json["meshes"][0]["primitives"][0]["mode"] = 1; }, "meshes",
                  "has no triangles, only 1 primitive of points or lines"},
        Malformed{"mode", [](Gltf& g) { g.json["meshes"][0]["primitives"][0]["mode"] = 7; },
                  "meshes[0].primitives[0]", "mode 7 is not a glTF primitive mode"},
        Malformed{"sparse",
                  [](Gltf& g) {
                    g.json["accessors"][0]["sparse"] = {
                        {"count", 1},
                        {"indices", {{"bufferView", 1}, {"componentType", 5123}}},
                        {"values", {{"bufferView", 0}}}};
                  },
                  "accessors[0]", "is sparse, which airlight does not read: export the model again without sparse accessors"},
        Malformed{"no_position", [](Gltf& g) { g.json["meshes"][0]["primitives"][0]["attributes"].erase("POSITION"); },
                  "meshes[0].primitives[0]", "has no POSITION attribute"},
        Malformed{"nan",
                  [](Gltf& g) {
                    const float nan = std::numeric_limits<float>::quiet_NaN();
                    std::memcpy(g.bin.data() + 12 + 4, &nan, 4);  // vertex 1's y
                  },
                  "accessors[0]", "element 1 is not finite"},
        Malformed{"index_range",
                  [](Gltf& g) {
                    const uint16_t three = 3;
                    std::memcpy(g.bin.data() + 36 + 4, &three, 2);  // the third index
                  },
                  "accessors[1]", "element 2 is 3, past the last of 3 vertices"},
        Malformed{"short_view", [](Gltf& g) { g.json["accessors"][0]["count"] = 4; }, "accessors[0]",
                  "runs past the end of bufferViews[0]"},
        Malformed{"required_extension",
                  [](Gltf& g) { g.json["extensionsRequired"] = {"KHR_draco_mesh_compression"}; },
                  "extensionsRequired[0]",
                  "\"KHR_draco_mesh_compression\" is not supported: export the model again without it (airlight "
                  "reads KHR_lights_punctual and ignores KHR_materials_*)"},
        Malformed{"meshopt", [](Gltf& g) { g.json["extensionsRequired"] = {"EXT_meshopt_compression"}; },
                  "extensionsRequired[0]",
                  "\"EXT_meshopt_compression\" is not supported: export the model again without it (airlight "
                  "reads KHR_lights_punctual and ignores KHR_materials_*)"},
        Malformed{"quantization", [](Gltf& g) { g.json["extensionsRequired"] = {"KHR_mesh_quantization"}; },
                  "extensionsRequired[0]",
                  "\"KHR_mesh_quantization\" is not supported: export the model again without it (airlight "
                  "reads KHR_lights_punctual and ignores KHR_materials_*)"},
        Malformed{"outside", [](Gltf& g) { g.json["images"] = {{{"uri", "../outside.png"}}}; }, "uri",
                  "\"../outside.png\" is outside the file's folder: airlight reads only the files beside a glTF "
                  "or in folders below it"},
        Malformed{"cycle", [](Gltf& g) { g.json["nodes"][0]["children"] = {0}; }, "nodes[0]",
                  "is reached twice from the scene (a node has at most one parent)"},
        Malformed{"missing_light",
                  [](Gltf& g) { g.json["nodes"][0]["extensions"]["KHR_lights_punctual"]["light"] = 2; },
                  "nodes[0].extensions.KHR_lights_punctual.light",
                  "refers to extensions.KHR_lights_punctual.lights[2], which does not exist"},
        Malformed{"wide_spot",
                  [](Gltf& g) {
                    const int spot = g.light({{"type", "spot"}, {"spot", {{"outerConeAngle", 2}}}});
                    g.node({{"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}});
                  },
                  "extensions.KHR_lights_punctual.lights[0].spot.outerConeAngle", "must be in (0, pi/2]"},
        Malformed{"orthographic",
                  [](Gltf& g) {
                    g.json["cameras"] = {{{"type", "orthographic"},
                                          {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}}};
                    g.node({{"camera", 0}});
                  },
                  "cameras[0]", "is orthographic: airlight renders perspective cameras only"},
        Malformed{"depth_range",
                  [](Gltf& g) {
                    g.json["cameras"] = {{{"type", "perspective"},
                                          {"perspective", {{"yfov", 0.5}, {"znear", 0.001}, {"zfar", 1000}}}}};
                    g.node({{"camera", 0}});
                  },
                  "cameras[0].perspective.zfar",
                  "far/near = 1e+06 is above the 100000 airlight supports (depth precision)"},
        // The message is the scene file reader's (scene_json_test holds its wording); the key
        // shows that reader ran inside extras.airlight.
        Malformed{"fog_key",
                  [](Gltf& g) { g.json["scenes"][0]["extras"] = {{"airlight", {{"medium", {{"scatter", 0.1}}}}}}; },
                  "scenes[0].extras.airlight.medium.scatter", ""}),
    [](const testing::TestParamInfo<Malformed>& info) { return std::string(info.param.name); });

// Not glTF at all: tinygltf's own message, on one line, without nlohmann's exception id.
TEST(GltfScene, AFileThatIsNotGltfFailsNamingTheFile) {
  const fs::path glb = work_dir() / "text.glb", gltf = work_dir() / "text.gltf";
  std::ofstream(glb) << "a text file, not a binary glTF";
  std::ofstream(gltf) << "{\"asset\": ";
  EXPECT_TRUE(throws_input_error([&] { load_scene(glb); }, glb.string(), "", "not a valid glTF file: Invalid magic."));
  EXPECT_TRUE(throws_input_error([&] { load_scene(gltf); }, gltf.string(), "",
                                 "not a valid glTF file: parse error at line 1, column 11: syntax error while "
                                 "parsing value - unexpected end of input; expected '[', '{', or a literal"));
}

}  // namespace
}  // namespace airlight
