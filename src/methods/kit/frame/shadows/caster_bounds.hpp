#pragma once
// What the shadow maps must cover: the bounds of the meshes that cast shadows.
#include <airlight/scene.hpp>
#include <glm/common.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

namespace airlight::kit {

struct Bounds {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  bool empty() const { return !(lo.x <= hi.x); }
  glm::dvec3 corner(int k) const { return {(k & 1 ? hi : lo).x, (k & 2 ? hi : lo).y, (k & 4 ? hi : lo).z}; }
  void add(const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

// Object-space bounds of one mesh as the shadow maps see it: empty for a mesh
// that casts no shadow, which they neither draw nor need to cover (an
// enclosure around a small scene spread a sun's map over the room, and its
// texels were many pixels wide at casters beside the eye: random scenes 169, 573).
Bounds caster_bounds(const Mesh& mesh);
// World bounds of the meshes this frame: each mesh's box corners through its
// transform (none: where the scene put it).
Bounds world_bounds(const std::vector<Bounds>& meshes, const std::vector<glm::mat4>& transforms);

}  // namespace airlight::kit
