#include "geometry/conforming_set.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace airlight::geometry {
namespace {

// The median of the pieces' largest box sides: a grid cell holds a few
// vertices where the pieces are small. A cell from the extent instead (the
// backplate's, far beyond the casters) put a dense caster's every vertex into
// one cell, and each edge then tested them all.
double typical_size(const std::vector<BeamPolygon>& pieces, double tolerance) {
  std::vector<double> sizes;
  for (const BeamPolygon& p : pieces) {
    if (p.vertices.empty()) continue;
    glm::dvec3 lo = p.vertices.front(), hi = lo;
    for (const glm::dvec3& v : p.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const glm::dvec3 side = hi - lo;
    sizes.push_back(std::max({side.x, side.y, side.z}));
  }
  if (sizes.empty()) return 4.0 * tolerance;
  std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
  return std::max(sizes[sizes.size() / 2], 4.0 * tolerance);
}

}  // namespace

size_t ConformingSet::KeyHash::operator()(const Key& k) const {
  return std::hash<long long>()(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
}

ConformingSet::ConformingSet(const std::vector<BeamPolygon>& pieces, double tolerance)
    : tolerance_(tolerance), cell_(typical_size(pieces, tolerance)) {
  glm::dvec3 lo(INFINITY);
  for (const auto& p : pieces)
    for (const glm::dvec3& v : p.vertices) lo = glm::min(lo, v);
  if (std::isfinite(lo.x)) origin_ = lo;
  for (const auto& p : pieces) {
    std::vector<int> loop;
    for (const glm::dvec3& v : p.vertices) loop.push_back(weld(v));
    loops_.push_back(std::move(loop));
  }
}

std::vector<int> ConformingSet::conforming(size_t k) const {
  std::vector<int> out;
  const std::vector<int>& loop = loops_[k];
  for (size_t e = 0; e < loop.size(); ++e) {
    const int a = loop[e], b = loop[(e + 1) % loop.size()];
    if (a == b) continue;
    out.push_back(a);
    for (int m : on_edge(a, b)) out.push_back(m);
  }
  return out;
}

bool ConformingSet::collinear(int a, int b, int c) const {
  const glm::dvec3 d = vertices_[c] - vertices_[a];
  const double length = glm::length(d);
  return length > 0.0 && glm::length(glm::cross(vertices_[b] - vertices_[a], d)) / length <= tolerance_;
}

ConformingSet::Key ConformingSet::key(const glm::dvec3& x) const {
  const glm::dvec3 c = glm::floor((x - origin_) / cell_);
  return {static_cast<long long>(c.x), static_cast<long long>(c.y), static_cast<long long>(c.z)};
}

int ConformingSet::weld(const glm::dvec3& v) {
  const Key k = key(v);
  for (long long dx = -1; dx <= 1; ++dx)
    for (long long dy = -1; dy <= 1; ++dy)
      for (long long dz = -1; dz <= 1; ++dz) {
        const auto it = grid_.find({k[0] + dx, k[1] + dy, k[2] + dz});
        if (it == grid_.end()) continue;
        for (int id : it->second)
          if (glm::distance(vertices_[id], v) <= tolerance_) return id;
      }
  vertices_.push_back(v);
  grid_[k].push_back(static_cast<int>(vertices_.size()) - 1);
  return static_cast<int>(vertices_.size()) - 1;
}

// Whether vertex id lies strictly inside segment p → p + d within the tolerance; s its parameter.
bool ConformingSet::near_edge(int id, const glm::dvec3& p, const glm::dvec3& d, double length2, double& s) const {
  s = glm::dot(vertices_[id] - p, d) / length2;
  return s > 0.0 && s < 1.0 && glm::distance(p + s * d, vertices_[id]) <= tolerance_;
}

// The welded vertices strictly inside segment a → b within the tolerance of it, from a to b:
// from the grid cells of the segment's box, or from every vertex when those outnumber them
// (a long edge, such as the backplate's).
std::vector<int> ConformingSet::on_edge(int a, int b) const {
  const glm::dvec3 p = vertices_[a], q = vertices_[b], d = q - p;
  const double length2 = glm::dot(d, d);
  std::vector<std::pair<double, int>> found;
  const Key lo = key(glm::min(p, q) - tolerance_), hi = key(glm::max(p, q) + tolerance_);
  const double cells = double(hi[0] - lo[0] + 1) * double(hi[1] - lo[1] + 1) * double(hi[2] - lo[2] + 1);
  double s = 0.0;
  if (cells > double(vertices_.size())) {
    for (int id = 0; id < static_cast<int>(vertices_.size()); ++id)
      if (id != a && id != b && near_edge(id, p, d, length2, s)) found.emplace_back(s, id);
  } else {
    for (long long x = lo[0]; x <= hi[0]; ++x)
      for (long long y = lo[1]; y <= hi[1]; ++y)
        for (long long z = lo[2]; z <= hi[2]; ++z) {
          const auto it = grid_.find({x, y, z});
          if (it == grid_.end()) continue;
          for (int id : it->second)
            if (id != a && id != b && near_edge(id, p, d, length2, s)) found.emplace_back(s, id);
        }
  }
  std::sort(found.begin(), found.end());
  std::vector<int> ids;
  for (const auto& f : found) ids.push_back(f.second);
  return ids;
}

}  // namespace airlight::geometry
