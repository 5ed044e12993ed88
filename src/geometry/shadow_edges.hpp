#pragma once
// Shadow-volume bookkeeping for Biri's shadow planes (Biri §5.1.1): for one caster and one
// light, the quads extruded from the caster's edges away from the light, each with the change
// of shadow count its crossing brings, so that a view ray's lit intervals follow from the
// count at the eye.
//
// count(p) = the number of the caster's triangles that the segment from the light to p
// properly crosses (a directional light travelling along unit D: the ray from p toward −D);
// p is lit by the caster iff count(p) = 0. Each triangle t shadows its volume, bounded near
// its edge (a, b) by the wedge
//   W(a, b) = { L + s·((1−u)·a + u·b − L) : s ≥ 1, u ∈ [0, 1] }   (point and spot at L),
//   W(a, b) = { (1−u)·a + u·b + s·D : s ≥ 0, u ∈ [0, 1] }          (directional).
// With the edge's normal n = (a − L) × (b − L) (directional: D × (b − a)) and c the third
// vertex of t, side_t = sign(n · (c − L)) (directional: sign(n · (c − a))); the edge's weight
// is w = Σ_t side_t. Crossing W(a, b) along dir changes count by +w if n · dir > 0, by −w
// otherwise. Interior edges of a smooth surface have w = 0, silhouette edges of a closed mesh
// ±2, boundary edges of an open mesh ±1: a closed mesh's planes are its silhouette edges, and
// an open, non-manifold or self-intersecting mesh gets exactly the triangle volumes' sides it
// needs. The count also changes by +1 where a path crosses a triangle away from the light;
// a view ray, which ends at the first surface it meets, never does.
#include <airlight/scene.hpp>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

namespace airlight::geometry {

// A triangle beside an edge: `along` = +1 when it runs the edge from a to b, −1 from b to a.
struct EdgeTriangle {
  uint32_t triangle;  // index into CasterTopology::triangles
  int along;
};

// A caster welded by position, with each edge's triangles (Biri §5.1.1). Built once per mesh.
struct CasterTopology {
  std::vector<glm::vec3> positions;    // welded, object space: each position's first occurrence
  std::vector<uint32_t> welded_index;  // per input vertex: its index in `positions`
  // Re-indexed by `welded_index`, of nonzero area: the triangles that shadow.
  std::vector<glm::uvec3> triangles;
  // Distinct indices but collinear (to double precision; exactly collinear ones always): kept
  // for `closed`, but they shadow nothing, so no edge lists them and shadow_count skips them.
  std::vector<glm::uvec3> zero_area_triangles;
  // The edges of `triangles`, (a, b) with a < b, sorted; edge e's triangles are
  // edge_triangles[edge_first[e] .. edge_first[e + 1]).
  std::vector<glm::uvec2> edges;
  std::vector<uint32_t> edge_first;
  std::vector<EdgeTriangle> edge_triangles;
  bool closed = false;  // every edge in exactly 2 triangles, which run it in opposite directions
  int collapsed_triangles = 0;  // dropped: welding gave them two equal indices
};

// Welds by exact position (−0 = +0). Throws airlight::Failure on an index out of range.
CasterTopology build_topology(std::span<const glm::vec3> positions,
                              std::span<const glm::uvec3> triangles);

struct LightOrigin {
  bool directional = false;
  glm::vec3 position{0.0f};        // point and spot
  glm::vec3 direction{0, -1, 0};   // directional: the way light travels, unit
};

// Where a scene light's shadows start: a spot shadows as a point (its cone is applied apart).
LightOrigin light_origin(const Light& light);

// A plane: the wedge W(a, b), world space, a and b the edge's ends in CasterTopology::edges'
// order (a < b by welded index), so that its n is (a − L) × (b − L), or D × (b − a).
struct ShadowPlane {
  glm::vec3 a, b;
  int weight;
};

struct ShadowPlaneStats {
  int planes = 0;
  int silhouette_edges = 0;  // planes of edges with 2 or more triangles
  int boundary_edges = 0;    // planes of edges with exactly one triangle
};

// Appends the caster's planes (edges with w ≠ 0) for one light. `world` holds the caster's
// welded positions in world space (CasterTopology::positions through the object's matrix).
// O(edges); allocates nothing but what `out` grows by. Throws airlight::Failure when `world`
// does not match the topology.
ShadowPlaneStats append_shadow_planes(const CasterTopology& caster,
                                      std::span<const glm::vec3> world, const LightOrigin& light,
                                      std::vector<ShadowPlane>& out);

// The planes linked into loops by their shared vertices (Biri links the silhouette into
// loops): the number of connected loops. For diagnostics: it allocates, unlike the above.
int shadow_plane_loops(const CasterTopology& caster, std::span<const glm::vec3> world,
                       const LightOrigin& light);

// count(p), by brute force over the caster's triangles in double precision
// (Möller–Trumbore): the count at the eye, one point per light and frame.
int shadow_count(const CasterTopology& caster, std::span<const glm::vec3> world,
                 const LightOrigin& light, const glm::vec3& p);

}  // namespace airlight::geometry
