// The on-disk reference cache (issue 6): a hit returns the stored frame, and
// any change to the scene's content changes the key.
#include "reference/cache.hpp"

#include "core/warning.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <sstream>

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

std::string bytes_of(const fs::path& file) {
  std::stringstream text;
  text << std::ifstream(file, std::ios::binary).rdbuf();
  return text.str();
}

// 64-bit FNV-1a, written out here as the format (README "The reference cache") states it.
std::string fnv1a(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ull;
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

// A damaged entry is reported with `warning` (after "<file>: "), rendered
// again and stored whole: the next call reads it, with no warning.
void expect_rendered_again(const Scene& scene, const fs::path& dir, const CachedReference& first,
                           const std::string& warning) {
  const fs::path file = dir / (reference_key(scene, 16, 12) + ".ref");
  {
    CapturedWarnings warnings;
    const CachedReference again = cached_reference(scene, 16, 12, dir);
    EXPECT_FALSE(again.cached);
    EXPECT_EQ(again.airlight.pixels, first.airlight.pixels);
    EXPECT_EQ(warnings.text(), "airlight: warning: " + file.string() + ": " + warning + "\n");
  }
  CapturedWarnings warnings;
  EXPECT_TRUE(cached_reference(scene, 16, 12, dir).cached);
  EXPECT_EQ(warnings.text(), "");
}

// The entry's first line and the bytes after it.
std::pair<std::string, std::string> split_entry(const fs::path& file) {
  const std::string text = bytes_of(file);
  const size_t eol = text.find('\n');
  return {text.substr(0, eol), text.substr(eol + 1)};
}

TEST(ReferenceCache, ATruncatedEntryIsRenderedAgainWithAWarning) {
  const fs::path dir = fresh_dir("airlight_reference_cache_truncated");
  const Scene scene = spot_over_floor();
  const CachedReference first = cached_reference(scene, 16, 12, dir);
  const fs::path file = dir / (reference_key(scene, 16, 12) + ".ref");
  const size_t body = split_entry(file).second.size();  // a JSON line, then 2 × 16 × 12 pixels of 12 bytes
  EXPECT_EQ(body, split_entry(file).second.find('\n') + 1 + 2 * 16 * 12 * 12);
  fs::resize_file(file, fs::file_size(file) - 100);
  expect_rendered_again(scene, dir, first,
                        "size check failed: " + std::to_string(body - 100) +
                            " bytes after the first line, which says " + std::to_string(body) +
                            "; rendering the reference again");
  fs::remove_all(dir);
}

TEST(ReferenceCache, AFlippedByteIsFoundByTheChecksum) {
  const fs::path dir = fresh_dir("airlight_reference_cache_flipped");
  const Scene scene = spot_over_floor();
  const CachedReference first = cached_reference(scene, 16, 12, dir);
  const fs::path file = dir / (reference_key(scene, 16, 12) + ".ref");
  auto [line, body] = split_entry(file);
  EXPECT_EQ(line, "airlight-reference-entry/1 fnv1a64=" + fnv1a(body) + " bytes=" + std::to_string(body.size()));
  body[body.size() - 7] ^= 0x10;  // one bit of a surface pixel
  std::ofstream(file, std::ios::binary) << line << '\n' << body;
  expect_rendered_again(scene, dir, first,
                        "checksum check failed: the content's FNV-1a is " + fnv1a(body) + ", the first line says " +
                            line.substr(line.find('=') + 1, 16) + "; rendering the reference again");
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
