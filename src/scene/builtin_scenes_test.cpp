#include "scene/test_support.hpp"

#include <airlight/scene.hpp>
#include <algorithm>
#include <gtest/gtest.h>

namespace airlight {
namespace {

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
    for (const Mesh& mesh : scene.meshes) EXPECT_TRUE(well_formed(mesh));
  }
}

TEST(BuiltinScenes, IncludeTheDocumentsScenes) {
  const auto names = builtin_scene_names();
  for (const char* name : {"teapot_spot", "biri_sphere", "nilsson_toplight", default_builtin})
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

TEST(BuiltinScenes, ToplightUsesNilssonsSimplifiedModel) {
  const Scene scene = builtin_scene("nilsson_toplight");
  EXPECT_EQ(scene.light_model.type, LightModelType::simplified);
  EXPECT_EQ(scene.lights[0].direction, glm::vec3(0, -1, 0));
}

TEST(BuiltinScenes, UnknownNameIsAnInputError) {
  EXPECT_TRUE(throws_input_error([] { builtin_scene("no_such_scene"); }, "<builtin>",
                                 "no_such_scene"));
}

}  // namespace
}  // namespace airlight
