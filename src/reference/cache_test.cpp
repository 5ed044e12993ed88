// The on-disk reference cache (issue 6): a hit returns the stored frame, and
// any change to the scene's content changes the key.
#include "reference/cache.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <memory>

namespace airlight::reference {
namespace {

namespace fs = std::filesystem;

// A spot with a 2×2 gobo in fog over a floor quad.
Scene spot_over_floor() {
  Scene scene;
  scene.medium.sigma_s = Color(0.1f);
  Light spot;
  spot.type = LightType::spot;
  spot.position = {0, 3, 0};
  spot.intensity = Color(50.0f);
  spot.cone_deg = 25.0f;
  spot.gobo_up = {0, 0, 1};
  Image gobo(2, 2, glm::vec3(1.0f));
  gobo.at(1, 0) = glm::vec3(0.2f);
  spot.gobo = std::make_shared<const Image>(gobo);
  scene.lights.push_back(spot);
  Mesh floor;
  floor.positions = {{-4, 0, -4}, {4, 0, -4}, {4, 0, 4}, {-4, 0, 4}};
  floor.normals.assign(4, {0, 1, 0});
  floor.triangles = {{0, 2, 1}, {0, 3, 2}};
  scene.meshes.push_back(floor);
  return scene;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

TEST(ReferenceCache, SecondCallReadsTheCache) {
  const fs::path dir = fresh_dir("airlight_reference_cache_test");
  const Scene scene = spot_over_floor();
  const CachedReference first = cached_reference(scene, 16, 12, dir);
  EXPECT_FALSE(first.cached);
  const CachedReference second = cached_reference(scene, 16, 12, dir);
  EXPECT_TRUE(second.cached);
  EXPECT_EQ(second.seconds, first.seconds);
  EXPECT_EQ(second.airlight.pixels, first.airlight.pixels);
  EXPECT_EQ(second.surface.pixels, first.surface.pixels);
  double sum = 0.0;
  for (const auto& p : first.airlight.pixels) sum += p.r;
  EXPECT_GT(sum, 0.0);  // the scene has airlight, so equality above means something
  fs::remove_all(dir);
}

TEST(ReferenceCache, KeyChangesWithTheScenesContentSizeAndSettings) {
  const Scene scene = spot_over_floor();
  const std::string key = reference_key(scene, 16, 12);
  EXPECT_EQ(key.size(), 16u);
  EXPECT_EQ(reference_key(spot_over_floor(), 16, 12), key);
  EXPECT_NE(reference_key(scene, 16, 13), key);

  Scene moved = spot_over_floor();
  moved.lights[0].position.x += 1e-4f;
  EXPECT_NE(reference_key(moved, 16, 12), key);

  Scene texel = spot_over_floor();
  Image gobo = *texel.lights[0].gobo;
  gobo.at(0, 1).g = 0.5f;
  texel.lights[0].gobo = std::make_shared<const Image>(gobo);
  EXPECT_NE(reference_key(texel, 16, 12), key);

  Scene vertex = spot_over_floor();
  vertex.meshes[0].positions[2].z = 4.5f;
  EXPECT_NE(reference_key(vertex, 16, 12), key);

  Scene no_shadow = spot_over_floor();
  no_shadow.meshes[0].casts_shadows = false;  // the same triangles, another image
  EXPECT_NE(reference_key(no_shadow, 16, 12), key);

  EXPECT_EQ(reference_key(scene, 16, 12, Settings{}), key);
  EXPECT_NE(reference_key(scene, 16, 12, {.min_segments = 256}), key);
  EXPECT_NE(reference_key(scene, 16, 12, {.rel_tol = 1e-4}), key);
  EXPECT_NE(reference_key(scene, 16, 12, {.subpixel = {0.5, 0.52}}), key);

  Scene lobe = spot_over_floor();
  lobe.medium.phase.lobes[0].g = 0.3f;
  EXPECT_NE(reference_key(lobe, 16, 12), key);
}

}  // namespace
}  // namespace airlight::reference
