#pragma once
// What the kit's buffers need from the settings and the scene (MethodInfo::memory,
// docs/design.md §5): each method's registration adds up the parts it uses, so
// that a frame beyond the memory available is refused before any GL allocation.
#include "methods/kit/frame/shadows/shadow_projection.hpp"

#include <airlight/method.hpp>
#include <string>
#include <vector>

namespace airlight::kit {

// How many lights of the scene get a 2D shadow map and how many a cube map
// (shadow_kind over the scene's bounds as loaded).
struct ShadowCounts {
  int maps = 0, cubes = 0;
};
ShadowCounts shadow_counts(const Scene& scene);
// The kind of map each light of the scene gets, in order.
std::vector<int> shadow_kinds(const Scene& scene);

// The shadow maps at "shadow_resolution": R32F layers and cube faces, and the
// depth target they are drawn through. None when no light gets a map.
std::vector<MemoryNeed> shadow_map_needs(const Scene& scene, const Settings& settings);

// The scene's meshes as SceneFrame uploads them: a vertex of 40 bytes, and 12
// (indices) and 16 (face normal) a triangle.
MemoryNeed geometry_need(const Scene& scene);

// Triangles of the scene's shadow casters and their count.
double caster_triangles(const Scene& scene);
int caster_count(const Scene& scene);

// "1 point light", "3 spot lights": a count with its noun, plural past one.
std::string counted(double count, const std::string& noun);
// "2048²"
std::string squared(int side);

}  // namespace airlight::kit
