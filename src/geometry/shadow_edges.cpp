#include "geometry/shadow_edges.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <tuple>
#include <unordered_map>

#include <glm/geometric.hpp>

namespace airlight::geometry {
namespace {

// Positions that compare equal hash alike: adding +0 turns −0 into +0.
struct PositionHash {
  size_t operator()(const glm::vec3& p) const {
    size_t h = 0;
    for (int k = 0; k < 3; ++k) h = (h ^ std::hash<float>()(p[k] + 0.0f)) * 1099511628211u;
    return h;
  }
};

void weld(std::span<const glm::vec3> positions, CasterTopology& caster) {
  std::unordered_map<glm::vec3, uint32_t, PositionHash> index_of;
  index_of.reserve(positions.size());
  caster.welded_index.reserve(positions.size());
  for (const glm::vec3& p : positions) {
    const auto [it, added] = index_of.try_emplace(p, static_cast<uint32_t>(caster.positions.size()));
    if (added) caster.positions.push_back(p);
    caster.welded_index.push_back(it->second);
  }
}

enum class Shape { collapsed, zero_area, shadowing };

Shape shape_of(const glm::uvec3& t, const std::vector<glm::vec3>& p) {
  if (t.x == t.y || t.y == t.z || t.z == t.x) return Shape::collapsed;
  // Zero exactly when collinear: the float differences are exact in double, and a cross
  // product's two equal terms round alike.
  const glm::dvec3 a(p[t.x]);
  const glm::dvec3 n = glm::cross(glm::dvec3(p[t.y]) - a, glm::dvec3(p[t.z]) - a);
  return n == glm::dvec3(0.0) ? Shape::zero_area : Shape::shadowing;
}

// One triangle's use of an edge, before the edges are gathered.
struct HalfEdge {
  glm::uvec2 edge;  // (a, b), a < b
  int along;        // +1 when the triangle runs a → b
  uint32_t triangle;
  bool shadows;     // false for a zero-area triangle: it counts only for closedness
};

void add_half_edges(const glm::uvec3& t, uint32_t triangle, bool shadows,
                    std::vector<HalfEdge>& out) {
  for (int k = 0; k < 3; ++k) {
    const uint32_t from = t[k], to = t[(k + 1) % 3];
    out.push_back({{std::min(from, to), std::max(from, to)}, from < to ? 1 : -1, triangle, shadows});
  }
}

// Sorts the half-edges by edge and gathers each edge's shadowing triangles (CSR).
void gather_edges(std::vector<HalfEdge> half, CasterTopology& caster) {
  const auto key = [](const HalfEdge& h) { return std::tie(h.edge.x, h.edge.y, h.triangle); };
  std::sort(half.begin(), half.end(), [&](const HalfEdge& l, const HalfEdge& r) { return key(l) < key(r); });
  caster.closed = true;
  caster.edge_first.assign(1, 0);
  for (size_t i = 0, j = 0; i < half.size(); i = j) {
    int along = 0;
    const size_t first = caster.edge_triangles.size();
    for (j = i; j < half.size() && half[j].edge == half[i].edge; ++j) {
      along += half[j].along;
      if (half[j].shadows) caster.edge_triangles.push_back({half[j].triangle, half[j].along});
    }
    caster.closed = caster.closed && j - i == 2 && along == 0;
    if (caster.edge_triangles.size() == first) continue;  // only zero-area triangles: no volume
    caster.edges.push_back(half[i].edge);
    caster.edge_first.push_back(static_cast<uint32_t>(caster.edge_triangles.size()));
  }
}

void check_world(const CasterTopology& caster, std::span<const glm::vec3> world) {
  if (world.size() != caster.positions.size())
    throw Failure("shadow planes: " + std::to_string(world.size()) + " world positions for a caster of " +
                  std::to_string(caster.positions.size()));
}

// side_t of each edge of t taken in t's own winding: the determinant
// [a − L, b − L, c − L] = N·(a − L), N = (b − a) × (c − a), is the same for the three
// rotations of (a, b, c) (directional: [D, b − a, c − a] = N·D). Every edge of t evaluates it
// from t's stored order, so rounding can flip a whole triangle nearly edge-on to the light
// (whose volume is then a sliver), never one of its edges against the others.
int facing(const glm::uvec3& t, std::span<const glm::vec3> world, const LightOrigin& light) {
  const glm::dvec3 a(world[t.x]);
  const glm::dvec3 n = glm::cross(glm::dvec3(world[t.y]) - a, glm::dvec3(world[t.z]) - a);
  const double side =
      glm::dot(n, light.directional ? glm::dvec3(light.direction) : a - glm::dvec3(light.position));
  return (side > 0.0) - (side < 0.0);
}

// Calls f(edge index, w) for each edge with w ≠ 0 (header: w = Σ_t side_t).
template <class F>
void for_each_plane(const CasterTopology& caster, std::span<const glm::vec3> world,
                    const LightOrigin& light, F&& f) {
  check_world(caster, world);
  for (size_t e = 0; e < caster.edges.size(); ++e) {
    int w = 0;
    for (uint32_t k = caster.edge_first[e]; k < caster.edge_first[e + 1]; ++k) {
      const EdgeTriangle& t = caster.edge_triangles[k];
      w += t.along * facing(caster.triangles[t.triangle], world, light);
    }
    if (w != 0) f(e, w);
  }
}

// Möller–Trumbore: whether origin + t·dir, 0 < t < t_max, passes strictly inside (a, b, c).
bool crosses(const glm::dvec3& origin, const glm::dvec3& dir, double t_max, const glm::dvec3& a,
             const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a, q = glm::cross(dir, e2);
  const double det = glm::dot(e1, q);
  if (det == 0.0) return false;  // the path runs in the triangle's plane
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, q) / det;
  if (!(u > 0.0 && u < 1.0)) return false;
  const glm::dvec3 r = glm::cross(s, e1);
  const double v = glm::dot(dir, r) / det;
  if (!(v > 0.0 && u + v < 1.0)) return false;
  const double t = glm::dot(e2, r) / det;
  return t > 0.0 && t < t_max;
}

}  // namespace

CasterTopology build_topology(std::span<const glm::vec3> positions,
                              std::span<const glm::uvec3> triangles) {
  CasterTopology caster;
  weld(positions, caster);
  std::vector<HalfEdge> half;
  half.reserve(3 * triangles.size());
  for (const glm::uvec3& input : triangles) {
    if (glm::max(input.x, glm::max(input.y, input.z)) >= positions.size())
      throw Failure("shadow planes: a triangle's index is out of range");
    const glm::uvec3 t(caster.welded_index[input.x], caster.welded_index[input.y],
                       caster.welded_index[input.z]);
    switch (shape_of(t, caster.positions)) {
    case Shape::collapsed: ++caster.collapsed_triangles; break;
    case Shape::zero_area:
      add_half_edges(t, static_cast<uint32_t>(caster.zero_area_triangles.size()), false, half);
      caster.zero_area_triangles.push_back(t);
      break;
    case Shape::shadowing:
      add_half_edges(t, static_cast<uint32_t>(caster.triangles.size()), true, half);
      caster.triangles.push_back(t);
      break;
    }
  }
  gather_edges(std::move(half), caster);
  return caster;
}

LightOrigin light_origin(const Light& light) {
  return {light.type == LightType::directional, light.position, light.direction};
}

ShadowPlaneStats append_shadow_planes(const CasterTopology& caster,
                                      std::span<const glm::vec3> world, const LightOrigin& light,
                                      std::vector<ShadowPlane>& out) {
  ShadowPlaneStats stats;
  for_each_plane(caster, world, light, [&](size_t e, int w) {
    const glm::uvec2 edge = caster.edges[e];
    out.push_back({world[edge.x], world[edge.y], w});
    const bool boundary = caster.edge_first[e + 1] - caster.edge_first[e] == 1;
    ++stats.planes;
    ++(boundary ? stats.boundary_edges : stats.silhouette_edges);
  });
  return stats;
}

int shadow_plane_loops(const CasterTopology& caster, std::span<const glm::vec3> world,
                       const LightOrigin& light) {
  // Union-find over the welded vertices: each new vertex adds a loop, each union removes one.
  std::vector<uint32_t> root(caster.positions.size());
  std::iota(root.begin(), root.end(), 0u);
  std::vector<bool> on_plane(caster.positions.size(), false);
  const auto find = [&](uint32_t v) {
    while (root[v] != v) v = root[v] = root[root[v]];
    return v;
  };
  int loops = 0;
  const auto add = [&](uint32_t v) {
    if (on_plane[v]) return;
    on_plane[v] = true;
    ++loops;
  };
  for_each_plane(caster, world, light, [&](size_t e, int) {
    const glm::uvec2 edge = caster.edges[e];
    add(edge.x);
    add(edge.y);
    const uint32_t a = find(edge.x), b = find(edge.y);
    if (a == b) return;
    root[a] = b;
    --loops;
  });
  return loops;
}

int shadow_count(const CasterTopology& caster, std::span<const glm::vec3> world,
                 const LightOrigin& light, const glm::vec3& p) {
  check_world(caster, world);
  // The path that shadows p: from the light to p, or from p toward −D without end.
  const glm::dvec3 target(p);
  const glm::dvec3 origin = light.directional ? target : glm::dvec3(light.position);
  const glm::dvec3 dir = light.directional ? -glm::dvec3(light.direction) : target - origin;
  const double t_max = light.directional ? std::numeric_limits<double>::infinity() : 1.0;
  int count = 0;
  for (const glm::uvec3& t : caster.triangles)
    count += crosses(origin, dir, t_max, glm::dvec3(world[t.x]), glm::dvec3(world[t.y]),
                     glm::dvec3(world[t.z]));
  return count;
}

}  // namespace airlight::geometry
