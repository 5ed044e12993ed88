// save_scene is load_scene's inverse: load → save → load gives the same Scene.
#include <airlight/error.hpp>
#include <airlight/scene.hpp>

#include <filesystem>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <string>
#include <unistd.h>

namespace airlight {
namespace {

// Directions are normalized on reading, which may move a unit vector's last
// bit; everything else reads back exactly (floats print with 9 digits).
constexpr float direction_tolerance = 1e-6f;

void expect_same(const glm::vec3& a, const glm::vec3& b, float tolerance = 0.0f) {
  EXPECT_LE(glm::distance(a, b), tolerance) << a.x << " " << a.y << " " << a.z << " vs " << b.x << " " << b.y
                                            << " " << b.z;
}

void expect_same_phase(const Phase& a, const Phase& b) {
  ASSERT_EQ(a.lobes.size(), b.lobes.size());
  for (size_t i = 0; i < a.lobes.size(); ++i) {
    EXPECT_EQ(a.lobes[i].type, b.lobes[i].type);
    EXPECT_EQ(a.lobes[i].g, b.lobes[i].g);
    EXPECT_NEAR(a.lobes[i].weight, b.lobes[i].weight, 1e-6f);
  }
}

void expect_same_light(const Light& a, const Light& b) {
  EXPECT_EQ(a.type, b.type);
  expect_same(a.position, b.position);
  expect_same(a.direction, b.direction, direction_tolerance);
  expect_same(a.intensity, b.intensity);
  expect_same(a.irradiance, b.irradiance);
  EXPECT_EQ(a.cone_deg, b.cone_deg);
  EXPECT_EQ(a.edge_deg, b.edge_deg);
  expect_same(a.gobo_up, b.gobo_up, direction_tolerance);
  ASSERT_EQ(bool(a.gobo), bool(b.gobo));
  if (a.gobo) {
    EXPECT_EQ(a.gobo->pixels, b.gobo->pixels);
  }
  ASSERT_EQ(a.beam.has_value(), b.beam.has_value());
  if (a.beam) {
    expect_same(a.beam->origin, b.beam->origin);
    EXPECT_EQ(a.beam->size, b.beam->size);
    EXPECT_EQ(a.beam->length, b.beam->length);
  }
}

// The OBJ reader numbers vertices in the order faces first use them, so
// triangles are compared by their corners, not by index.
void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (size_t t = 0; t < a.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      expect_same(a.positions[a.triangles[t][k]], b.positions[b.triangles[t][k]]);
      expect_same(a.normals[a.triangles[t][k]], b.normals[b.triangles[t][k]], direction_tolerance);
    }
  expect_same(a.albedo, b.albedo);
  EXPECT_EQ(a.casts_shadows, b.casts_shadows);
}

void expect_same_scene(const Scene& a, const Scene& b) {
  expect_same(a.camera.position, b.camera.position);
  expect_same(a.camera.look_at, b.camera.look_at);
  expect_same(a.camera.up, b.camera.up, direction_tolerance);
  EXPECT_EQ(a.camera.fov_y_deg, b.camera.fov_y_deg);
  EXPECT_EQ(a.camera.near, b.camera.near);
  EXPECT_EQ(a.camera.far, b.camera.far);
  expect_same(a.medium.sigma_s, b.medium.sigma_s);
  expect_same(a.medium.sigma_a, b.medium.sigma_a);
  expect_same_phase(a.medium.phase, b.medium.phase);
  EXPECT_EQ(a.light_model.type, b.light_model.type);
  EXPECT_EQ(a.light_model.a0, b.light_model.a0);
  EXPECT_EQ(a.light_model.a1, b.light_model.a1);
  expect_same(a.ambient, b.ambient);
  ASSERT_EQ(a.volumes.size(), b.volumes.size());
  for (size_t i = 0; i < a.volumes.size(); ++i) {
    expect_same(a.volumes[i].min, b.volumes[i].min);
    expect_same(a.volumes[i].max, b.volumes[i].max);
    expect_same(a.volumes[i].sigma_s, b.volumes[i].sigma_s);
    expect_same(a.volumes[i].sigma_a, b.volumes[i].sigma_a);
    expect_same_phase(a.volumes[i].phase, b.volumes[i].phase);
  }
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (size_t i = 0; i < a.lights.size(); ++i) expect_same_light(a.lights[i], b.lights[i]);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i) expect_same_mesh(a.meshes[i], b.meshes[i]);
}

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("airlight_scene_writer_" + std::to_string(getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

class SceneWriter : public ::testing::TestWithParam<std::string> {};

// Every built-in scene: gobos (stage), beams (stained_glass, nilsson_parallel),
// volumes (biri_media), the simplified light model (nilsson_*), phase sums.
TEST_P(SceneWriter, BuiltinSavedAndLoadedIsTheSameScene) {
  const Scene original = builtin_scene(GetParam());
  const auto file = fresh_dir(GetParam()) / "saved.json";
  save_scene(original, file);
  const Scene loaded = load_scene(file);
  EXPECT_EQ(loaded.name, original.name);
  expect_same_scene(original, loaded);
  // And once more from the loaded scene, whose meshes now carry the loader's names.
  const auto again = file.parent_path() / "again.json";
  save_scene(loaded, again);
  expect_same_scene(loaded, load_scene(again));
}

INSTANTIATE_TEST_SUITE_P(Builtins, SceneWriter, ::testing::ValuesIn(builtin_scene_names()),
                         [](const auto& info) { return info.param; });

TEST(SceneWriterNames, OnlyJsonIsWritten) {
  EXPECT_THROW(save_scene(builtin_scene("teapot_spot"), fresh_dir("ext") / "scene.txt"), InputError);
}

}  // namespace
}  // namespace airlight
