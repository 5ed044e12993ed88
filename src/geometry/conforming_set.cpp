#include "geometry/conforming_set.hpp"

#include "geometry/segment_box.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace airlight::geometry {
namespace {

// The median of the pieces' largest box sides: a grid cell holds a few
// vertices where the pieces are small. A cell from the extent instead (the
// backplate's, far beyond the casters) put a dense caster's every vertex into
// one cell, and each weld then tested them all.
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
  order_.resize(vertices_.size());
  for (size_t id = 0; id < order_.size(); ++id) order_[id] = static_cast<int>(id);
  if (!vertices_.empty()) build(0, static_cast<int>(order_.size()));
}

std::vector<int> ConformingSet::conforming(size_t k) const {
  std::vector<int> out, stack;
  std::vector<std::pair<double, int>> found;
  const std::vector<int>& loop = loops_[k];
  for (size_t e = 0; e < loop.size(); ++e) {
    const int a = loop[e], b = loop[(e + 1) % loop.size()];
    if (a == b) continue;
    out.push_back(a);
    on_edge(a, b, out, found, stack);
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

// The cells within the tolerance of v: its own, and a neighbour across a face only where v
// is that near it (twice the tolerance, for the rounding of the cell coordinates), most
// often none, as cells are a typical piece's size.
int ConformingSet::weld(const glm::dvec3& v) {
  const Key k = key(v);
  const glm::dvec3 inside = (v - origin_) / cell_ - glm::dvec3(k[0], k[1], k[2]), near = 2.0 * tolerance_ / glm::dvec3(cell_);
  const glm::ivec3 lo = -glm::ivec3(glm::lessThanEqual(inside, near)), hi = glm::ivec3(glm::greaterThanEqual(inside, 1.0 - near));
  for (long long dx = lo.x; dx <= hi.x; ++dx)
    for (long long dy = lo.y; dy <= hi.y; ++dy)
      for (long long dz = lo.z; dz <= hi.z; ++dz) {
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

// Splits order_[begin, end) at the median of its box's widest side, down to a
// few vertices a leaf; returns the node's index.
int ConformingSet::build(int begin, int end) {
  constexpr int leaf_size = 8;
  const int index = static_cast<int>(nodes_.size());
  nodes_.push_back({vertices_[order_[begin]], vertices_[order_[begin]], begin, end});
  for (int i = begin; i < end; ++i) {
    nodes_[index].lo = glm::min(nodes_[index].lo, vertices_[order_[i]]);
    nodes_[index].hi = glm::max(nodes_[index].hi, vertices_[order_[i]]);
  }
  if (end - begin <= leaf_size) return index;
  const glm::dvec3 side = nodes_[index].hi - nodes_[index].lo;
  const int axis = side.x >= side.y && side.x >= side.z ? 0 : side.y >= side.z ? 1 : 2;
  const int middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](int a, int b) { return vertices_[a][axis] < vertices_[b][axis]; });
  const int left = build(begin, middle), right = build(middle, end);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

// The welded vertices strictly inside segment a → b within the tolerance of it, from a to b:
// from the k-d tree's boxes the segment passes within the tolerance of. A grid's cells
// over the segment's box made a long edge (a floor piece's, across a million small
// pieces' cells) test every vertex: quadratic (docs/decisions.md "A million triangles").
void ConformingSet::on_edge(int a, int b, std::vector<int>& out, std::vector<std::pair<double, int>>& found,
                            std::vector<int>& stack) const {
  const glm::dvec3 p = vertices_[a], d = vertices_[b] - p;
  const double length2 = glm::dot(d, d);
  found.clear();
  stack.clear();
  if (!nodes_.empty()) stack.push_back(0);
  double s = 0.0;
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    if (!segment_meets_box(p, d, node.lo - tolerance_, node.hi + tolerance_)) continue;
    if (node.left >= 0) {
      stack.push_back(node.left);
      stack.push_back(node.right);
      continue;
    }
    for (int i = node.begin; i < node.end; ++i) {
      const int id = order_[i];
      if (id != a && id != b && near_edge(id, p, d, length2, s)) found.emplace_back(s, id);
    }
  }
  std::sort(found.begin(), found.end());
  for (const auto& f : found) out.push_back(f.second);
}

}  // namespace airlight::geometry
