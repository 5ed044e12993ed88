#pragma once
// Polygons that tile a surface made conforming: vertices within a tolerance
// welded, and every edge split at the vertices that lie on it (T-junctions,
// where a beam tree cut one piece and not its neighbour), so that two pieces
// share an edge vertex for vertex. A rasterizer covers each pixel of a
// conforming tiling exactly once (OpenGL's rule for shared edges); along a
// T-junction it may cover a pixel twice or not at all. Used for the pyramids
// over a beam tree's visible set (beam_volumes) and the virtual planes cut
// into regions (the kit's slab regions).
#include "geometry/beam_tree.hpp"

#include <array>
#include <glm/vec3.hpp>
#include <unordered_map>
#include <vector>

namespace airlight::geometry {

class ConformingSet {
public:
  ConformingSet(const std::vector<BeamPolygon>& pieces, double tolerance);

  // Piece k's loop of welded vertices with every vertex that lies on one of its edges inserted.
  std::vector<int> conforming(size_t k) const;
  // Piece k's loop of welded vertices as given, nothing inserted.
  const std::vector<int>& welded(size_t k) const { return loops_[k]; }
  const glm::dvec3& vertex(int id) const { return vertices_[id]; }
  // Whether b lies within the tolerance of the line through a and c.
  bool collinear(int a, int b, int c) const;
  size_t size() const { return loops_.size(); }

private:
  using Key = std::array<long long, 3>;
  struct KeyHash {
    size_t operator()(const Key& k) const;
  };
  // A node of the k-d tree over the welded vertices (built once they are all
  // welded): its box and its range of order_, or its two children.
  struct Node {
    glm::dvec3 lo, hi;
    int begin = 0, end = 0, left = -1, right = -1;
  };
  Key key(const glm::dvec3& x) const;
  int weld(const glm::dvec3& v);
  int build(int begin, int end);
  // Appends to `out`; `found` and `stack` are the search's, kept between calls (no allocation per edge).
  void on_edge(int a, int b, std::vector<int>& out, std::vector<std::pair<double, int>>& found,
               std::vector<int>& stack) const;
  bool near_edge(int id, const glm::dvec3& p, const glm::dvec3& d, double length2, double& s) const;

  double tolerance_, cell_ = 1.0;
  glm::dvec3 origin_{0.0};
  std::vector<glm::dvec3> vertices_;
  std::vector<std::vector<int>> loops_;
  std::unordered_map<Key, std::vector<int>, KeyHash> grid_;  // for welding
  std::vector<int> order_;                                    // vertex ids, the tree's leaves' ranges
  std::vector<Node> nodes_;                                   // the root first
};

}  // namespace airlight::geometry
