#include "methods/kit/method/memory_needs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace airlight::kit {

std::vector<int> shadow_kinds(const Scene& scene) {
  std::vector<Bounds> meshes;
  for (const Mesh& mesh : scene.meshes) meshes.push_back(caster_bounds(mesh));
  const Bounds bounds = world_bounds(meshes, {});
  std::vector<int> kinds;
  for (const Light& light : scene.lights) kinds.push_back(shadow_kind(light, bounds, nullptr));
  return kinds;
}

ShadowCounts shadow_counts(const Scene& scene) {
  ShadowCounts counts;
  for (const int kind : shadow_kinds(scene)) {
    counts.maps += kind == shadow_map;
    counts.cubes += kind == shadow_cube;
  }
  return counts;
}

// SceneFrame::allocate_shadow_maps: the maps' layers, six faces per cube, and
// one depth target of the map's size, all 4 bytes a texel.
std::vector<MemoryNeed> shadow_map_needs(const Scene& scene, const Settings& settings) {
  const ShadowCounts counts = shadow_counts(scene);
  if (counts.maps + counts.cubes == 0) return {};
  const int r = settings.integer("shadow_resolution");
  const double texels = double(r) * r * (counts.maps + 6.0 * counts.cubes + 1.0);
  std::string what = "the shadow maps of " + counted(counts.maps + counts.cubes, "light") + " (";
  if (counts.maps) what += counted(counts.maps, "map") + (counts.cubes ? " and " : "");
  if (counts.cubes) what += counted(counts.cubes, "cube") + " of 6 faces";
  const double face = 4.0 * r * r, largest = std::max(counts.maps * face, 6.0 * counts.cubes * face);
  return {{"shadow_resolution", what + ", " + squared(r) + " texels of 4 bytes each)", 4.0 * texels, 0.0, largest}};
}

MemoryNeed geometry_need(const Scene& scene) {
  double vertices = 0.0, triangles = 0.0;
  for (const Mesh& mesh : scene.meshes) {
    vertices += static_cast<double>(mesh.positions.size());
    triangles += static_cast<double>(mesh.triangles.size());
  }
  const double buffer = std::max(40.0 * vertices, 16.0 * triangles);
  return {"", "the scene's " + counted(triangles, "triangle") + " on the GPU", 40.0 * vertices + 28.0 * triangles, buffer};
}

double caster_triangles(const Scene& scene) {
  double count = 0.0;
  for (const Mesh& mesh : scene.meshes)
    if (mesh.casts_shadows) count += static_cast<double>(mesh.triangles.size());
  return count;
}

int caster_count(const Scene& scene) {
  int count = 0;
  for (const Mesh& mesh : scene.meshes) count += mesh.casts_shadows;
  return count;
}

std::string counted(double count, const std::string& noun) {
  char text[32];
  std::snprintf(text, sizeof text, "%.0f ", count);
  return text + noun + (count == 1.0 ? "" : "s");
}

std::string squared(int side) { return std::to_string(side) + "²"; }

}  // namespace airlight::kit
