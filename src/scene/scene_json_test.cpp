#include "core/image_io.hpp"
#include "scene/test_support.hpp"

#include <airlight/scene.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace airlight {
namespace {

using Json = nlohmann::json;
using scene_test::data_dir;
using scene_test::throws_input_error;
using scene_test::well_formed;

// Inline scenes are parsed as if they sat in the test data folder, so that
// relative paths like "cube.obj" resolve; the file itself need not exist.
std::string inline_file() { return (data_dir() / "inline.json").string(); }

Scene parse(const Json& json) { return parse_scene(json.dump(), inline_file()); }

Json valid_scene() {
  std::ifstream in(data_dir() / "valid.json");
  return Json::parse(in);
}

void expect_vec(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-6f) {
  EXPECT_NEAR(glm::distance(actual, expected), 0.0f, tolerance)
      << "(" << actual.x << ", " << actual.y << ", " << actual.z << ")";
}

// ---- valid scenes ----------------------------------------------------------

TEST(SceneJson, ValidSceneParsesToTheRightValues) {
  const auto file = data_dir() / "valid.json";
  const Scene s = load_scene(file);
  EXPECT_EQ(s.name, "valid");
  EXPECT_EQ(s.source, file);
  expect_vec(s.camera.position, {0, 2, 8});
  expect_vec(s.camera.look_at, {0, 1, 0});
  expect_vec(s.camera.up, {0, 1, 0});  // normalized
  EXPECT_EQ(s.camera.fov_y_deg, 50.0f);
  EXPECT_EQ(s.camera.near, 0.1f);
  EXPECT_EQ(s.camera.far, 40.0f);
  expect_vec(s.medium.sigma_s, {0.04f, 0.05f, 0.06f});
  expect_vec(s.medium.sigma_a, glm::vec3(0.01f));
  EXPECT_EQ(s.light_model.type, LightModelType::physical);
  expect_vec(s.ambient, {0.01f, 0.02f, 0.03f});

  ASSERT_EQ(s.volumes.size(), 1u);
  expect_vec(s.volumes[0].min, {-1, 0, -1});
  expect_vec(s.volumes[0].max, {1, 2, 1});
  expect_vec(s.volumes[0].sigma_s, {0.3f, 0, 0});
  ASSERT_EQ(s.volumes[0].phase.lobes.size(), 1u);
  EXPECT_EQ(s.volumes[0].phase.lobes[0].type, PhaseType::murky);
}

TEST(SceneJson, NestedPhaseSumsFlattenIntoWeightedLobes) {
  const auto& lobes = load_scene(data_dir() / "valid.json").medium.phase.lobes;
  ASSERT_EQ(lobes.size(), 3u);
  EXPECT_EQ(lobes[0].type, PhaseType::rayleigh);
  EXPECT_FLOAT_EQ(lobes[0].weight, 0.25f);
  EXPECT_EQ(lobes[1].type, PhaseType::henyey_greenstein);
  EXPECT_FLOAT_EQ(lobes[1].g, 0.5f);
  EXPECT_FLOAT_EQ(lobes[1].weight, 0.375f);
  EXPECT_EQ(lobes[2].type, PhaseType::schlick);
  EXPECT_FLOAT_EQ(lobes[2].g, -0.2f);
  EXPECT_FLOAT_EQ(lobes[2].weight, 0.375f);
}

TEST(SceneJson, LightsAreReadAndDirectionsNormalized) {
  const Scene s = load_scene(data_dir() / "valid.json");
  ASSERT_EQ(s.lights.size(), 3u);
  EXPECT_EQ(s.lights[0].type, LightType::point);
  expect_vec(s.lights[0].position, {2, 3, 1});
  expect_vec(s.lights[0].intensity, {50, 40, 30});

  const Light& spot = s.lights[1];
  EXPECT_EQ(spot.type, LightType::spot);
  expect_vec(spot.direction, {0, -1, 0});
  expect_vec(spot.intensity, glm::vec3(200));
  EXPECT_EQ(spot.cone_deg, 25.0f);
  EXPECT_EQ(spot.edge_deg, 5.0f);
  EXPECT_EQ(spot.gobo, nullptr);
  expect_vec(spot.gobo_up, {0, 0, 1});  // the axis is vertical

  EXPECT_EQ(s.lights[2].type, LightType::directional);
  expect_vec(s.lights[2].direction, {0, -0.6f, 0.8f});
  expect_vec(s.lights[2].irradiance, glm::vec3(2));
}

TEST(SceneJson, ObjectsBecomePlacedMeshes) {
  const Scene s = load_scene(data_dir() / "valid.json");
  ASSERT_EQ(s.meshes.size(), 6u);
  for (const Mesh& mesh : s.meshes) EXPECT_TRUE(well_formed(mesh));
  EXPECT_EQ(s.meshes[0].name, "objects[0] (teapot)");
  EXPECT_EQ(s.meshes[4].name, "objects[4] (pillar)");
  EXPECT_EQ(s.meshes[5].name, "objects[5] (cube.obj)");
  expect_vec(s.meshes[0].albedo, glm::vec3(0.5f));
  expect_vec(s.meshes[1].albedo, glm::vec3(0.7f));  // the default
  expect_vec(s.meshes[5].albedo, {0.6f, 0.6f, 0.5f});
  EXPECT_TRUE(s.meshes[0].casts_shadows);  // the default
  // Teapot at scale 2: 2 units tall.
  float top = 0.0f;
  for (const glm::vec3& p : s.meshes[0].positions) top = std::max(top, p.y);
  EXPECT_NEAR(top, 2.0f, 1e-5f);
  // The cube moved 3 along x.
  for (const glm::vec3& p : s.meshes[5].positions) EXPECT_GE(p.x, 3.0f);
  // The plane faces +z at z = -3.
  for (const glm::vec3& p : s.meshes[3].positions) EXPECT_FLOAT_EQ(p.z, -3.0f);
  for (const glm::vec3& n : s.meshes[3].normals) expect_vec(n, {0, 0, 1});
}

// A few bytes make a million triangles: a sphere of 1024 segments has 1 046 528. The third
// takes the scene over its limit, counted as each object is added.
TEST(SceneJson, MoreThanTwoMillionTrianglesInAllAreRefused) {
  const std::string sphere = R"({"shape": "sphere", "radius": 1, "segments": 1024})";
  const std::string text = R"({"format": "airlight-scene/1", "objects": [)" + sphere + "," + sphere + "," + sphere + "]}";
  EXPECT_TRUE(throws_input_error([&] { parse_scene(text, "big.json"); }, "big.json", "objects[2]",
                                 "the scene's meshes have more than 2097152 triangles in all"));
}

// The boxes are read in the object's coordinates and carried by its transform: the sphere's
// outer box, off-centre by 0.1 along x, turned 90° about y (x → −z) and moved by (1, 0, 0).
TEST(SceneJson, BoundingBoxesMoveWithTheirObject) {
  Json j = valid_scene();
  j["objects"][1]["outer_box"] = {{"min", {-0.5, 0.5, -0.5}}, {"max", {0.7, 1.5, 0.5}}};
  j["objects"][1]["inner_box"] = {{"min", {-0.2, 0.8, -0.2}}, {"max", {0.2, 1.2, 0.2}}};
  j["objects"][1]["rotate_deg"] = {0, 90, 0};
  j["objects"][1]["translate"] = {1, 0, 0};
  const Scene scene = parse(j);
  const Mesh& sphere = scene.meshes[1];
  ASSERT_TRUE(sphere.outer_box && sphere.inner_box);
  expect_vec(sphere.outer_box->center, {1, 1, -0.1f});
  expect_vec(sphere.outer_box->axes[0], {0, 0, -1});
  expect_vec(sphere.outer_box->half, {0.6f, 0.5f, 0.5f});
  expect_vec(sphere.inner_box->center, {1, 1, 0});
  expect_vec(sphere.inner_box->half, glm::vec3(0.2f));
  EXPECT_FALSE(parse(valid_scene()).meshes[1].outer_box);  // none unless given
}

TEST(SceneJson, AnObjectMayCastNoShadow) {
  Json j = valid_scene();
  j["objects"][1]["casts_shadows"] = false;
  const Scene s = parse(j);
  EXPECT_FALSE(s.meshes[1].casts_shadows);
  EXPECT_TRUE(s.meshes[2].casts_shadows);
}

TEST(SceneJson, MinimalSceneTakesTheDefaults) {
  const Scene s = load_scene(data_dir() / "minimal.json");
  const Camera camera;
  EXPECT_EQ(s.name, "minimal");
  EXPECT_EQ(s.camera.position, camera.position);
  EXPECT_EQ(s.camera.fov_y_deg, camera.fov_y_deg);
  EXPECT_EQ(s.medium.sigma_s, glm::vec3(0.0f));
  ASSERT_EQ(s.medium.phase.lobes.size(), 1u);
  EXPECT_EQ(s.medium.phase.lobes[0].type, PhaseType::isotropic);
  EXPECT_EQ(s.ambient, glm::vec3(0.0f));
  EXPECT_TRUE(s.lights.empty());
  EXPECT_TRUE(s.meshes.empty());
  EXPECT_TRUE(s.volumes.empty());
}

TEST(SceneJson, EmptyObjectsListIsValid) {
  Json j = valid_scene();
  j["objects"] = Json::array();
  EXPECT_TRUE(parse(j).meshes.empty());
}

TEST(SceneJson, SimplifiedLightModelKeepsItsCoefficients) {
  Json j = valid_scene();
  j["light_model"] = {{"type", "simplified"}, {"a0", 0.5}, {"a1", 2}};
  const LightModel model = parse(j).light_model;
  EXPECT_EQ(model.type, LightModelType::simplified);
  EXPECT_EQ(model.a0, 0.5f);
  EXPECT_EQ(model.a1, 2.0f);
}

TEST(SceneJson, WeightsSummingToOneWithinTheToleranceAreAccepted) {
  Json j = valid_scene();
  j["medium"]["phase"] = Json::parse(R"({"type": "sum", "terms": [
      {"weight": 0.33333, "phase": {"type": "hazy"}},
      {"weight": 0.66667, "phase": {"type": "isotropic"}}]})");
  EXPECT_EQ(parse(j).medium.phase.lobes.size(), 2u);
}

TEST(SceneJson, SpotDefaultsAndLimits) {
  Json j = valid_scene();
  j["lights"][1].erase("edge_deg");
  j["lights"][1]["cone_deg"] = 180;  // a spot may light everything
  j["lights"][1]["direction"] = {1, -1, 0};
  const Light spot = parse(j).lights[1];
  EXPECT_EQ(spot.edge_deg, 0.0f);
  EXPECT_EQ(spot.cone_deg, 180.0f);
  expect_vec(spot.gobo_up, {0, 1, 0});  // world up for a tilted axis
}

TEST(SceneJson, ExplicitGoboUpIsNormalized) {
  Json j = valid_scene();
  j["lights"][1]["gobo_up"] = {3, 0, 4};
  expect_vec(parse(j).lights[1].gobo_up, {0.6f, 0, 0.8f});
}

TEST(SceneJson, GoboIsReadRelativeToTheSceneFile) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "airlight_scene_gobo";
  std::filesystem::create_directories(dir / "maps");
  write_image(Image(4, 2, {0.5f, 0.25f, 1.0f}), dir / "maps" / "dots.pfm");
  Json j = valid_scene();
  j["objects"] = Json::array();
  j["lights"][1]["gobo"] = "maps/dots.pfm";
  std::ofstream(dir / "gobo.json") << j.dump();
  const Light spot = load_scene(dir / "gobo.json").lights[1];
  ASSERT_NE(spot.gobo, nullptr);
  EXPECT_EQ(spot.gobo->width, 4);
  EXPECT_EQ(spot.gobo->height, 2);
  expect_vec(spot.gobo->at(3, 1), {0.5f, 0.25f, 1.0f});
  std::filesystem::remove_all(dir);
}

TEST(SceneJson, DirectionalBeamIsReadWithItsFrame) {
  Json j = valid_scene();
  j["lights"][2]["beam"] = Json::parse(R"({"origin": [1, 6, -2], "size": [3, 1.5], "length": 12})");
  const Light sun = parse(j).lights[2];
  ASSERT_TRUE(sun.beam.has_value());
  expect_vec(sun.beam->origin, {1, 6, -2});
  EXPECT_EQ(sun.beam->size, glm::vec2(3.0f, 1.5f));
  EXPECT_EQ(sun.beam->length, 12.0f);
  expect_vec(sun.gobo_up, {0, 1, 0});  // world up: the light is not vertical
  j["lights"][2]["direction"] = {0, -1, 0};
  expect_vec(parse(j).lights[2].gobo_up, {0, 0, 1});  // vertical: +z, as for a spot
  j["lights"][2]["gobo_up"] = {3, 0, 4};
  expect_vec(parse(j).lights[2].gobo_up, {0.6f, 0, 0.8f});
  j["lights"][2].erase("beam");
  j["lights"][2].erase("gobo_up");
  EXPECT_FALSE(parse(j).lights[2].beam.has_value());  // no beam: lit everywhere
}

// A PNG gobo on a beam, relative to the scene file, decoded from sRGB to linear
// (IEC 61966-2-1): the bytes 255, 128 (power segment) and 10 (linear segment).
TEST(SceneJson, PngGoboOnABeamIsDecodedToLinear) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "airlight_scene_png_gobo";
  std::filesystem::create_directories(dir);
  auto linear = [](int byte) {
    const double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  };
  Image image(2, 1);
  image.at(0, 0) = glm::vec3(linear(255), linear(128), linear(10));  // written back as exactly these bytes
  image.at(1, 0) = glm::vec3(linear(0), linear(10), linear(128));
  write_image(image, dir / "window.png", ToneMap{1.0f, ToneCurve::clamp});
  Json j = valid_scene();
  j["objects"] = Json::array();
  j["lights"][2]["beam"] = Json::parse(R"({"origin": [0, 6, 0], "size": [2, 1], "length": 10})");
  j["lights"][2]["gobo"] = "window.png";
  std::ofstream(dir / "beam.json") << j.dump();
  const Light sun = load_scene(dir / "beam.json").lights[2];
  ASSERT_NE(sun.gobo, nullptr);
  ASSERT_EQ(sun.gobo->width, 2);
  // 1e-6: float pixels of values <= 1.
  expect_vec(sun.gobo->at(0, 0), glm::vec3(1.0f, 0.2158605f, 0.0030353f), 1e-6f);
  expect_vec(sun.gobo->at(1, 0), glm::vec3(0.0f, 0.0030353f, 0.2158605f), 1e-6f);
  std::filesystem::remove_all(dir);
}

// ---- bad input: every error names the file and the key ----------------------

// One broken scene: the valid scene with the value at `pointer` replaced by
// `value` (JSON text), or removed when value is null.
struct BadCase {
  const char* name;
  const char* pointer;
  const char* value;
  const char* key;
  const char* message = "";  // what the error must say, when a row checks it; {dir} is data_dir()
};

void PrintTo(const BadCase& c, std::ostream* out) { *out << c.name; }

class BadScene : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScene, NamesTheFileAndTheKey) {
  const BadCase& c = GetParam();
  Json j = valid_scene();
  const Json::json_pointer pointer(c.pointer);
  if (c.value) j[pointer] = Json::parse(c.value);
  else j[pointer.parent_pointer()].erase(pointer.back());
  std::string message = c.message;
  if (const size_t at = message.find("{dir}"); at != std::string::npos) message.replace(at, 5, data_dir().string());
  EXPECT_TRUE(throws_input_error([&] { parse(j); }, inline_file(), c.key, message));
}

constexpr const char* erase = nullptr;

const BadCase kFormat[] = {
    {"FormatMissing", "/format", erase, "format"},
    {"FormatWrongVersion", "/format", R"("airlight-scene/2")", "format"},
    {"FormatNotString", "/format", "1", "format"},
};

// The message lists the keys valid where the unknown one is: a shape's own and every object's.
const BadCase kUnknownKeys[] = {
    {"TopLevel", "/colour", "1", "colour",
     "unknown key (known here: format, gltf, name, camera, medium, light_model, ambient, volumes, lights, objects)"},
    {"Camera", "/camera/zoom", "2", "camera.zoom",
     "unknown key (known here: position, look_at, up, fov_y_deg, near, far)"},
    {"Medium", "/medium/density", "1", "medium.density", "unknown key (known here: scattering, absorption, phase)"},
    {"Light", "/lights/1/colour", "1", "lights[1].colour",
     "unknown key (known here: type, position, direction, intensity, cone_deg, edge_deg, gobo_up, gobo)"},
    {"ConeOnPointLight", "/lights/0/cone_deg", "20", "lights[0].cone_deg",
     "unknown key (known here: type, position, intensity)"},
    {"BeamOnDirectionalLight", "/lights/2/cone_deg", "20", "lights[2].cone_deg",
     "unknown key (known here: type, direction, irradiance, beam)"},
    {"NestedPhase", "/medium/phase/terms/1/phase/terms/0/phase/k", "0.1",
     "medium.phase.terms[1].phase.terms[0].phase.k", "unknown key (known here: type, g)"},
    {"GOnIsotropic", "/volumes/0/phase", R"({"type": "isotropic", "g": 0.2})", "volumes[0].phase.g",
     "unknown key (known here: type)"},
    {"Term", "/medium/phase/terms/0/wieght", "0.1", "medium.phase.terms[0].wieght",
     "unknown key (known here: weight, phase)"},
    {"Volume", "/volumes/0/center", "[0, 0, 0]", "volumes[0].center",
     "unknown key (known here: shape, min, max, scattering, absorption, phase)"},
    {"Object", "/objects/1/radius2", "1", "objects[1].radius2",
     "unknown key (known here: shape, center, radius, segments, outer_box, inner_box, translate, rotate_deg, scale, albedo, casts_shadows, name)"},
    {"KeyOfAnotherShape", "/objects/2/radius", "1", "objects[2].radius",
     "unknown key (known here: shape, min, max, outer_box, inner_box, translate, rotate_deg, scale, albedo, casts_shadows, name)"},
    {"MeshObject", "/objects/5/segments", "8", "objects[5].segments", "unknown key (known here: mesh, outer_box, inner_box, translate, rotate_deg, scale, albedo, casts_shadows, name)"},
    {"A0OnPhysicalModel", "/light_model/a0", "1", "light_model.a0", "unknown key (known here: type)"},
};

const BadCase kWrongTypes[] = {
    {"CameraNotObject", "/camera", "[1, 2]", "camera"},
    {"VectorNotArray", "/camera/position", R"("here")", "camera.position"},
    {"VectorTooShort", "/camera/position", "[1, 2]", "camera.position"},
    {"VectorTooLong", "/camera/look_at", "[1, 2, 3, 4]", "camera.look_at"},
    {"VectorComponentString", "/camera/position/1", R"("a")", "camera.position[1]"},
    {"NumberBoolean", "/camera/fov_y_deg", "true", "camera.fov_y_deg"},
    {"NumberNull", "/camera/near", "null", "camera.near"},
    {"NameNumber", "/name", "3", "name"},
    {"LightsNotArray", "/lights", "{}", "lights"},
    {"LightNotObject", "/lights/0", "3", "lights[0]"},
    {"ObjectsNotArray", "/objects", R"("none")", "objects"},
    {"VolumesNotArray", "/volumes", "1", "volumes"},
    {"ColorString", "/medium/scattering", R"("grey")", "medium.scattering"},
    {"ColorPair", "/lights/0/intensity", "[1, 2]", "lights[0].intensity"},
    {"SegmentsFraction", "/objects/1/segments", "10.5", "objects[1].segments", "must be a whole number, got 10.5"},
    {"SegmentsTooFew", "/objects/1/segments", "3", "objects[1].segments", "must be in [4, 1024], got 3"},
    {"MeshPathNumber", "/objects/5/mesh", "1", "objects[5].mesh"},
    {"GoboNotString", "/lights/1/gobo", "7", "lights[1].gobo"},
    {"PhaseNotObject", "/medium/phase", R"("hg")", "medium.phase"},
    {"WeightString", "/medium/phase/terms/0/weight", R"("a")", "medium.phase.terms[0].weight"},
    {"LightTypeNumber", "/lights/0/type", "1", "lights[0].type"},
};

// Finite numbers beyond float range: a bounded value says its interval, an unbounded one the float's limit.
const BadCase kBeyondFloatRange[] = {
    {"Bounded", "/camera/fov_y_deg", "1e39", "camera.fov_y_deg", "must be in (0, 180), got 1e+39"},
    {"VectorComponent", "/lights/0/position/0", "-1e300", "lights[0].position[0]",
     "too small, at least -3.40282e+38, got -1e+300"},
    {"Color", "/lights/1/intensity", "1e39", "lights[1].intensity", "too large, at most 3.40282e+38, got 1e+39"},
    {"Ambient", "/ambient/1", "1e300", "ambient[1]", "too large, at most 3.40282e+38, got 1e+300"},
};

const BadCase kOutOfRange[] = {
    {"FovZero", "/camera/fov_y_deg", "0", "camera.fov_y_deg", "must be in (0, 180), got 0"},
    {"Fov180", "/camera/fov_y_deg", "180", "camera.fov_y_deg", "must be in (0, 180), got 180"},
    {"FovNegative", "/camera/fov_y_deg", "-10", "camera.fov_y_deg"},
    {"NearZero", "/camera/near", "0", "camera.near", "must be > 0, got 0"},
    {"NearNegative", "/camera/near", "-0.1", "camera.near"},
    {"FarBelowNear", "/camera/far", "0.05", "camera.far", "must be greater than near (0.1), got 0.05"},
    {"FarEqualsNear", "/camera/far", "0.1", "camera.far"},
    {"FarOverNear", "/camera/far", "2e5", "camera.far",
     "far/near = 2e+06 is above the 100000 airlight supports (depth precision)"},
    {"NegativeScattering", "/medium/scattering", "-0.1", "medium.scattering", "must be >= 0, got -0.1"},
    {"NegativeScatteringChannel", "/medium/scattering/1", "-0.01", "medium.scattering[1]"},
    {"NegativeAbsorption", "/medium/absorption", "-0.01", "medium.absorption"},
    {"NegativeVolumeScattering", "/volumes/0/scattering/0", "-1", "volumes[0].scattering[0]"},
    {"NegativeVolumeAbsorption", "/volumes/0/absorption", "-1", "volumes[0].absorption"},
    {"NegativeIntensityChannel", "/lights/0/intensity/2", "-1", "lights[0].intensity[2]"},
    {"NegativeSpotIntensity", "/lights/1/intensity", "-200", "lights[1].intensity"},
    {"NegativeIrradiance", "/lights/2/irradiance", "-2", "lights[2].irradiance"},
    {"NegativeAmbient", "/ambient/0", "-0.1", "ambient[0]"},
    {"ConeZero", "/lights/1/cone_deg", "0", "lights[1].cone_deg"},
    {"ConeAbove180", "/lights/1/cone_deg", "180.5", "lights[1].cone_deg", "must be in (0, 180], got 180.5"},
    {"EdgeNegative", "/lights/1/edge_deg", "-1", "lights[1].edge_deg"},
    {"EdgeAboveCone", "/lights/1/edge_deg", "26", "lights[1].edge_deg", "must be in [0, 25], got 26"},
    {"HgGOne", "/medium/phase/terms/1/phase/terms/0/phase/g", "1",
     "medium.phase.terms[1].phase.terms[0].phase.g", "must be in (-1, 1), got 1"},
    {"HgGMinusOne", "/medium/phase/terms/1/phase/terms/0/phase/g", "-1",
     "medium.phase.terms[1].phase.terms[0].phase.g"},
    {"HgGRoundingOntoOne", "/medium/phase/terms/1/phase/terms/0/phase/g", "0.99999999999",
     "medium.phase.terms[1].phase.terms[0].phase.g", "must be in (-1, 1), got 0.99999999999, which is 1 as a float"},
    {"SchlickGAboveOne", "/medium/phase/terms/1/phase/terms/1/phase/g", "1.5",
     "medium.phase.terms[1].phase.terms[1].phase.g"},
    {"HgWithoutG", "/volumes/0/phase", R"({"type": "henyey_greenstein"})", "volumes[0].phase.g"},
    {"UnknownPhase", "/volumes/0/phase/type", R"("mie")", "volumes[0].phase.type"},
    {"WeightsNotSummingToOne", "/medium/phase/terms/0/weight", "0.3", "medium.phase.terms"},
    {"NestedWeightsNotSummingToOne", "/medium/phase/terms/1/phase/terms/0/weight", "0.4",
     "medium.phase.terms[1].phase.terms"},
    {"NegativeWeight", "/medium/phase/terms/0/weight", "-0.25", "medium.phase.terms[0].weight"},
    {"NoTerms", "/medium/phase/terms", "[]", "medium.phase.terms"},
    {"SimplifiedNegativeA0", "/light_model", R"({"type": "simplified", "a0": -1, "a1": 1})",
     "light_model.a0"},
    {"SimplifiedNegativeA1", "/light_model", R"({"type": "simplified", "a1": -1})",
     "light_model.a1"},
    {"SimplifiedBothZero", "/light_model", R"({"type": "simplified", "a0": 0, "a1": 0})",
     "light_model"},
    {"UnknownLightModel", "/light_model", R"({"type": "magic"})", "light_model.type"},
    {"VolumeMinEqualsMax", "/volumes/0/max/1", "0", "volumes[0].max"},
    {"VolumeNotBox", "/volumes/0/shape", R"("sphere")", "volumes[0].shape"},
    {"BoxMinAboveMax", "/objects/2/min/0", "6", "objects[2].max"},
    {"SphereRadiusZero", "/objects/1/radius", "0", "objects[1].radius"},
    {"CylinderRadiusNegative", "/objects/4/radius", "-0.3", "objects[4].radius"},
    {"CylinderHeightZero", "/objects/4/height", "0", "objects[4].height"},
    {"ScaleZero", "/objects/0/scale", "0", "objects[0].scale"},
    {"ScaleNegative", "/objects/0/scale", "-2", "objects[0].scale"},
    {"AlbedoAboveOne", "/objects/0/albedo", "1.5", "objects[0].albedo"},
    {"CastsShadowsNotBoolean", "/objects/1/casts_shadows", "1", "objects[1].casts_shadows"},
    {"AlbedoChannelNegative", "/objects/5/albedo/1", "-0.1", "objects[5].albedo[1]"},
    {"PlaneSizeZero", "/objects/3/size/0", "0", "objects[3].size[0]"},
    {"ScaleOverflowsGeometry", "/objects/2/scale", "1e38", "objects[2]"},
    {"SphereTooSmallForFloats", "/objects/1",
     R"({"shape": "sphere", "center": [1, 1, 1], "radius": 1e-30})", "objects[1]"},
};

// Nilsson §5.1's bounding volumes: objects[1] is a sphere of radius 0.5 about (0, 1, 0),
// objects[2] the box (−5, −0.1, −5)–(5, 0, 5), objects[3] a plane (open).
const BadCase kBoundingBoxes[] = {
    {"OuterBoxCutsTheObject", "/objects/2/outer_box", R"({"min": [-5, -0.1, -5], "max": [4, 0, 5]})",
     "objects[2].outer_box", "does not enclose the object"},
    {"InnerBoxCrossesTheObject", "/objects/1/inner_box",
     R"({"min": [-0.2, 0.8, -0.2], "max": [0.2, 1.6, 0.2]})", "objects[1].inner_box",
     "is not inside the object"},
    {"InnerBoxBesideTheObject", "/objects/1/inner_box", R"({"min": [2, 2, 2], "max": [3, 3, 3]})",
     "objects[1].inner_box", "is not inside the object"},
    {"InnerBoxOfAnOpenMesh", "/objects/3/inner_box",
     R"({"min": [-0.1, -0.1, -3.1], "max": [0.1, 0.1, -2.9]})", "objects[3].inner_box",
     "an open mesh has no inside"},
    {"BoundingBoxMinAboveMax", "/objects/1/outer_box", R"({"min": [1, 2, 1], "max": [-1, 0, -1]})",
     "objects[1].outer_box.max", "must exceed min on every axis"},
    {"BoundingBoxUnknownKey", "/objects/1/inner_box",
     R"({"min": [-0.1, 0.9, -0.1], "max": [0.1, 1.1, 0.1], "center": [0, 1, 0]})",
     "objects[1].inner_box.center"},
};

const BadCase kZeroVectors[] = {
    {"SpotDirection", "/lights/1/direction", "[0, 0, 0]", "lights[1].direction"},
    {"DirectionalDirection", "/lights/2/direction", "[0, 0, 0]", "lights[2].direction"},
    {"CameraUp", "/camera/up", "[0, 0, 0]", "camera.up"},
    {"CameraUpAlongView", "/camera/up", "[0, -1, -8]", "camera.up"},
    {"LookAtIsPosition", "/camera/look_at", "[0, 2, 8]", "camera.look_at"},
    {"PlaneNormal", "/objects/3/normal", "[0, 0, 0]", "objects[3].normal"},
    {"GoboUp", "/lights/1/gobo_up", "[0, 0, 0]", "lights[1].gobo_up"},
    {"GoboUpAlongAxis", "/lights/1/gobo_up", "[0, 1, 0]", "lights[1].gobo_up"},
};

const BadCase kObjectsAndLights[] = {
    {"ShapeAndMesh", "/objects/1/mesh", R"("cube.obj")", "objects[1]"},
    {"NeitherShapeNorMesh", "/objects/1/shape", erase, "objects[1]"},
    {"UnknownShape", "/objects/1/shape", R"("torus")", "objects[1].shape"},
    {"MissingRadius", "/objects/1/radius", erase, "objects[1].radius", "is required"},
    {"MissingBoxMax", "/objects/2/max", erase, "objects[2].max"},
    {"MissingMeshFile", "/objects/5/mesh", R"("missing.obj")", "objects[5].mesh"},
    {"UnknownLightType", "/lights/0/type", R"("area")", "lights[0].type"},
    {"MissingLightType", "/lights/0/type", erase, "lights[0].type"},
    {"MissingPosition", "/lights/0/position", erase, "lights[0].position"},
    {"MissingCone", "/lights/1/cone_deg", erase, "lights[1].cone_deg"},
    {"MissingIrradiance", "/lights/2/irradiance", erase, "lights[2].irradiance"},
    {"MissingGoboFile", "/lights/1/gobo", R"("missing.png")", "lights[1].gobo",
     "file not found: {dir}/missing.png"},
    {"GoboOnWideCone", "/lights/1",
     R"({"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "intensity": 1,
         "cone_deg": 90, "gobo": "missing.png"})",
     "lights[1].cone_deg", "must be < 90 for a spot with a gobo, got 90"},
};

// Every missing required key of an object in one message; one missing names its own key.
const BadCase kMissingKeys[] = {
    {"CylinderRadiusAndHeight", "/objects/4", R"({"shape": "cylinder"})", "objects[4]",
     "missing required keys: radius, height"},
    {"BoxMinAndMax", "/objects/2", R"({"shape": "box", "albedo": 0.5})", "objects[2]",
     "missing required keys: min, max"},
    {"BoundingBoxMinAndMax", "/objects/1/outer_box", "{}", "objects[1].outer_box", "missing required keys: min, max"},
    {"PointLight", "/lights/0", R"({"type": "point"})", "lights[0]", "missing required keys: position, intensity"},
    {"SpotLight", "/lights/1", R"({"type": "spot", "intensity": 1})", "lights[1]",
     "missing required keys: position, direction, cone_deg"},
    {"DirectionalLight", "/lights/2", R"({"type": "directional"})", "lights[2]",
     "missing required keys: direction, irradiance"},
    {"Beam", "/lights/2/beam", "{}", "lights[2].beam", "missing required keys: origin, size, length"},
    {"Volume", "/volumes/0", R"({"min": [0, 0, 0]})", "volumes[0]", "missing required keys: shape, max"},
    {"PhaseTerm", "/medium/phase/terms/0", "{}", "medium.phase.terms[0]", "missing required keys: weight, phase"},
    {"OneOfTwo", "/lights/2/irradiance", erase, "lights[2].irradiance", "is required"},
};

// A beam and the keys that need one, on the valid scene's directional light (lights[2]).
const BadCase kBeams[] = {
    {"BeamOnPointLight", "/lights/0/beam", R"({"origin": [0, 5, 0], "size": [1, 1], "length": 5})",
     "lights[0].beam"},
    {"BeamOnSpotLight", "/lights/1/beam", R"({"origin": [0, 5, 0], "size": [1, 1], "length": 5})",
     "lights[1].beam"},
    {"BeamNotObject", "/lights/2/beam", "[1, 2]", "lights[2].beam"},
    {"BeamUnknownKey", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [1, 1], "length": 5, "width": 2})",
     "lights[2].beam.width"},
    {"BeamMissingOrigin", "/lights/2/beam", R"({"size": [1, 1], "length": 5})", "lights[2].beam.origin"},
    {"BeamMissingSize", "/lights/2/beam", R"({"origin": [0, 5, 0], "length": 5})", "lights[2].beam.size"},
    {"BeamMissingLength", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [1, 1]})", "lights[2].beam.length"},
    {"BeamSizeZero", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [0, 1], "length": 5})",
     "lights[2].beam.size[0]"},
    {"BeamSizeNegative", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [1, -1], "length": 5})",
     "lights[2].beam.size[1]"},
    {"BeamSizeThreeNumbers", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [1, 1, 1], "length": 5})",
     "lights[2].beam.size"},
    {"BeamSizeBeyondFloatRange", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [1e39, 1], "length": 5})",
     "lights[2].beam.size[0]"},
    {"BeamLengthZero", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [1, 1], "length": 0})",
     "lights[2].beam.length"},
    {"BeamLengthNegative", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [1, 1], "length": -3})",
     "lights[2].beam.length"},
    {"BeamLengthBeyondFloatRange", "/lights/2/beam", R"({"origin": [0, 5, 0], "size": [1, 1], "length": 1e39})",
     "lights[2].beam.length"},
    {"BeamOriginString", "/lights/2/beam", R"({"origin": "here", "size": [1, 1], "length": 5})",
     "lights[2].beam.origin"},
    {"GoboOnDirectionalWithoutBeam", "/lights/2/gobo", R"("missing.png")", "lights[2].gobo"},
    {"GoboUpOnDirectionalWithoutBeam", "/lights/2/gobo_up", "[0, 0, 1]", "lights[2].gobo_up"},
    {"BeamGoboUpAlongDirection", "/lights/2",
     R"({"type": "directional", "direction": [0, -1, 0], "irradiance": 1, "gobo_up": [0, 2, 0],
         "beam": {"origin": [0, 5, 0], "size": [1, 1], "length": 5}})",
     "lights[2].gobo_up"},
    {"BeamGoboMissingFile", "/lights/2",
     R"({"type": "directional", "direction": [0, -1, 0], "irradiance": 1, "gobo": "missing.png",
         "beam": {"origin": [0, 5, 0], "size": [1, 1], "length": 5}})",
     "lights[2].gobo"},
};

std::string case_name(const ::testing::TestParamInfo<BadCase>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Format, BadScene, ::testing::ValuesIn(kFormat), case_name);
INSTANTIATE_TEST_SUITE_P(UnknownKey, BadScene, ::testing::ValuesIn(kUnknownKeys), case_name);
INSTANTIATE_TEST_SUITE_P(WrongType, BadScene, ::testing::ValuesIn(kWrongTypes), case_name);
INSTANTIATE_TEST_SUITE_P(BeyondFloatRange, BadScene, ::testing::ValuesIn(kBeyondFloatRange), case_name);
INSTANTIATE_TEST_SUITE_P(OutOfRange, BadScene, ::testing::ValuesIn(kOutOfRange), case_name);
INSTANTIATE_TEST_SUITE_P(ZeroVector, BadScene, ::testing::ValuesIn(kZeroVectors), case_name);
INSTANTIATE_TEST_SUITE_P(ObjectOrLight, BadScene, ::testing::ValuesIn(kObjectsAndLights),
                         case_name);
INSTANTIATE_TEST_SUITE_P(MissingKeys, BadScene, ::testing::ValuesIn(kMissingKeys), case_name);
INSTANTIATE_TEST_SUITE_P(Beam, BadScene, ::testing::ValuesIn(kBeams), case_name);
INSTANTIATE_TEST_SUITE_P(BoundingBox, BadScene, ::testing::ValuesIn(kBoundingBoxes), case_name);

// ---- bad input the table cannot express ------------------------------------

TEST(SceneJson, MalformedJsonReportsTheParsersPosition) {
  const std::string text = "{\n  \"format\": \"airlight-scene/1\",\n}";
  EXPECT_TRUE(throws_input_error([&] { parse_scene(text, "bad.json"); }, "bad.json", ""));
  try {
    parse_scene(text, "bad.json");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 3"), std::string::npos) << e.what();
  }
}

// Beyond double range the lexer fails, before any key's interval is known.
TEST(SceneJson, NumberOverflowIsAnErrorNamingItsKey) {
  const std::string text = R"({"format": "airlight-scene/1", "ambient": 1e999})";
  EXPECT_TRUE(throws_input_error([&] { parse_scene(text, "big.json"); }, "big.json", "ambient",
                                 "too large, at most 3.40282e+38, got 1e999"));
  const std::string nested = R"({"format": "airlight-scene/1", "camera": {"position": [0, -1e999, 0]}})";
  EXPECT_TRUE(throws_input_error([&] { parse_scene(nested, "big.json"); }, "big.json", "camera.position[1]",
                                 "too small, at least -3.40282e+38, got -1e999"));
}

TEST(SceneJson, DuplicateKeyIsAnError) {
  const std::string text = R"({"format": "airlight-scene/1", "ambient": 1, "ambient": 2})";
  EXPECT_TRUE(throws_input_error([&] { parse_scene(text, "dup.json"); }, "dup.json", "ambient"));
}

TEST(SceneJson, TopLevelMustBeAnObject) {
  EXPECT_TRUE(throws_input_error([] { parse_scene("[1, 2]", "a.json"); }, "a.json", ""));
  EXPECT_TRUE(throws_input_error([] { parse_scene("", "a.json"); }, "a.json", ""));
}

TEST(SceneJson, MissingSceneFileNamesIt) {
  const auto file = data_dir() / "no_such_scene.json";
  EXPECT_TRUE(throws_input_error([&] { load_scene(file); }, file.string(), ""));
}

TEST(SceneJson, ObjErrorsNameTheObjFile) {
  Json j = valid_scene();
  j["objects"][5]["mesh"] = "bad_index.obj";
  EXPECT_TRUE(throws_input_error([&] { parse(j); }, (data_dir() / "bad_index.obj").string(), "face 1",
                                 "refers to a missing vertex"));
}

}  // namespace
}  // namespace airlight
