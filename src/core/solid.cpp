#include "core/solid.hpp"

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>
#include <map>
#include <utility>
#include <vector>

namespace airlight::solid {
namespace {

using Edge = std::pair<uint32_t, uint32_t>;

// The directed edges of the triangles welded by exact position, sorted; triangles that
// welding collapses (two equal indices) are left out, as build_topology drops them.
std::vector<Edge> welded_edges(std::span<const glm::vec3> positions,
                               std::span<const glm::uvec3> triangles) {
  std::map<std::array<float, 3>, uint32_t> index_of;  // + 0.0f: −0 and +0 are one position
  const auto welded = [&](uint32_t i) {
    const glm::vec3& p = positions[i];
    const std::array<float, 3> key{p.x + 0.0f, p.y + 0.0f, p.z + 0.0f};
    return index_of.try_emplace(key, uint32_t(index_of.size())).first->second;
  };
  std::vector<Edge> edges;
  for (const glm::uvec3& t : triangles) {
    const uint32_t w[3] = {welded(t.x), welded(t.y), welded(t.z)};
    if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0]) continue;
    for (int k = 0; k < 3; ++k) edges.emplace_back(w[k], w[(k + 1) % 3]);
  }
  std::sort(edges.begin(), edges.end());
  return edges;
}

// Möller–Trumbore in double: whether the ray from p along dir crosses the triangle ahead.
bool ray_crosses(const glm::dvec3& p, const glm::dvec3& dir, const glm::dvec3& a,
                 const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a, e2 = c - a, q = glm::cross(dir, e2);
  const double det = glm::dot(e1, q);
  if (det == 0.0) return false;  // the ray runs in the triangle's plane
  const glm::dvec3 s = p - a;
  const double u = glm::dot(s, q) / det;
  const glm::dvec3 r = glm::cross(s, e1);
  const double v = glm::dot(dir, r) / det;
  return u >= 0.0 && v >= 0.0 && u + v <= 1.0 && glm::dot(e2, r) / det > 0.0;
}

bool odd_crossings(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
                   const glm::dvec3& p, const glm::dvec3& dir) {
  bool odd = false;
  for (const glm::uvec3& t : triangles)
    odd ^= ray_crosses(p, dir, positions[t.x], positions[t.y], positions[t.z]);
  return odd;
}

// Whether the axis separates the triangle v from the box [−h, h] (Akenine-Möller 2001).
bool separates(const std::array<glm::dvec3, 3>& v, const glm::dvec3& axis, const glm::dvec3& h) {
  const double p0 = glm::dot(v[0], axis), p1 = glm::dot(v[1], axis), p2 = glm::dot(v[2], axis);
  const double r = glm::dot(h, glm::abs(axis));
  return std::min({p0, p1, p2}) > r || std::max({p0, p1, p2}) < -r;
}

}  // namespace

bool closed(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles) {
  const std::vector<Edge> edges = welded_edges(positions, triangles);
  if (edges.empty()) return false;
  for (size_t i = 0; i < edges.size(); ++i) {
    if (i + 1 < edges.size() && edges[i] == edges[i + 1]) return false;
    const Edge back{edges[i].second, edges[i].first};
    if (!std::binary_search(edges.begin(), edges.end(), back)) return false;
  }
  return true;
}

bool inside(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
            const glm::dvec3& p) {
  // Generic directions, so that no ray runs along a coordinate plane that shapes are built on.
  static const glm::dvec3 directions[3] = {
      glm::normalize(glm::dvec3(0.5772, 0.6181, 0.5335)),
      glm::normalize(glm::dvec3(-0.7071, 0.3183, -0.6324)),
      glm::normalize(glm::dvec3(0.2718, -0.8660, 0.4142))};
  int votes = 0;
  for (const glm::dvec3& dir : directions) votes += odd_crossings(positions, triangles, p, dir);
  return votes >= 2;
}

bool crosses(const OrientedBox& box, const glm::dvec3& a, const glm::dvec3& b,
             const glm::dvec3& c) {
  const glm::dmat3 axes(box.axes);
  const glm::dvec3 center(box.center), h(box.half);
  // In the box's frame, where it is [−h, h].
  const std::array<glm::dvec3, 3> v = {glm::transpose(axes) * (a - center),
                                       glm::transpose(axes) * (b - center),
                                       glm::transpose(axes) * (c - center)};
  const glm::dvec3 f[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
  if (separates(v, glm::cross(f[0], f[1]), h)) return false;
  for (int i = 0; i < 3; ++i) {
    glm::dvec3 e(0.0);
    e[i] = 1.0;
    if (separates(v, e, h)) return false;
    for (const glm::dvec3& edge : f)
      if (separates(v, glm::cross(e, edge), h)) return false;  // a zero axis separates nothing
  }
  return true;
}

bool box_inside(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
                const OrientedBox& box) {
  for (const glm::uvec3& t : triangles)
    if (crosses(box, positions[t.x], positions[t.y], positions[t.z])) return false;
  return inside(positions, triangles, box.center);
}

}  // namespace airlight::solid
