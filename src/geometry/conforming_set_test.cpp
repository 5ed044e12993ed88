// geometry/conforming_set: pieces that tile a square with T-junctions come out
// sharing every edge vertex for vertex, welded within the tolerance.
#include "geometry/conforming_set.hpp"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <utility>
#include <vector>

namespace airlight::geometry {
namespace {

BeamPolygon rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0, 0.0}, {x1, y0, 0.0}, {x1, y1, 0.0}, {x0, y1, 0.0}}, 0};
}

// A unit square cut into columns, each column cut into rows at its own
// heights: every vertical edge meets the neighbours' row corners (T-junctions),
// and the corners carry a jitter below the tolerance, so they must be welded.
std::vector<BeamPolygon> cut_square(std::mt19937& rng, double jitter) {
  std::uniform_real_distribution<double> cut(0.1, 0.9), wobble(-jitter, jitter);
  std::vector<BeamPolygon> pieces;
  const double columns[] = {0.0, 0.3, 0.55, 1.0};
  for (int c = 0; c < 3; ++c) {
    std::vector<double> rows = {0.0, cut(rng), 1.0};
    if (rows[1] > 0.5) rows.insert(rows.begin() + 1, 0.5 * rows[1]);
    for (size_t r = 0; r + 1 < rows.size(); ++r) {
      BeamPolygon p = rectangle(columns[c], rows[r], columns[c + 1], rows[r + 1]);
      for (glm::dvec3& v : p.vertices) v += glm::dvec3(wobble(rng), wobble(rng), 0.0);
      pieces.push_back(std::move(p));
    }
  }
  return pieces;
}

TEST(ConformingSet, TJunctionsBecomeSharedEdges) {
  std::mt19937 rng(7);
  const double tolerance = 1e-6;
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<BeamPolygon> pieces = cut_square(rng, 0.2 * tolerance);
    const ConformingSet set(pieces, tolerance);
    // Every directed edge of every conforming loop: an interior edge appears
    // once each way, a boundary edge (on the square's outline) once.
    std::map<std::pair<int, int>, int> edges;
    for (size_t k = 0; k < set.size(); ++k) {
      const std::vector<int> loop = set.conforming(k);
      for (size_t e = 0; e < loop.size(); ++e) ++edges[{loop[e], loop[(e + 1) % loop.size()]}];
    }
    int unmatched = 0;
    for (const auto& [edge, count] : edges) {
      EXPECT_EQ(count, 1);
      const glm::dvec3 a = set.vertex(edge.first), b = set.vertex(edge.second);
      const bool outline = (std::abs(a.x) < 1e-5 && std::abs(b.x) < 1e-5) || (std::abs(a.x - 1) < 1e-5 && std::abs(b.x - 1) < 1e-5) ||
                           (std::abs(a.y) < 1e-5 && std::abs(b.y) < 1e-5) || (std::abs(a.y - 1) < 1e-5 && std::abs(b.y - 1) < 1e-5);
      if (!outline && !edges.count({edge.second, edge.first})) ++unmatched;
    }
    EXPECT_EQ(unmatched, 0) << "trial " << trial;
  }
}

// A long edge (a backplate's) over many small pieces: the vertices on it are
// found whether the grid is searched or every vertex is (the cells of its box
// outnumber the vertices), in order along it.
TEST(ConformingSet, ALongEdgeGetsEveryVertexOnItInOrder) {
  std::vector<BeamPolygon> pieces;
  for (int k = 0; k < 100; ++k) pieces.push_back(rectangle(0.01 * k, 0.0, 0.01 * (k + 1), 0.01));
  pieces.push_back(rectangle(0.0, -1000.0, 1.0, 0.0));  // below all of them, its top edge under their bottoms
  const ConformingSet set(pieces, 1e-9);
  const std::vector<int> loop = set.conforming(pieces.size() - 1);
  ASSERT_EQ(loop.size(), 4u + 99u);  // its corners and the 99 interior bottom corners of the strip
  // The top edge runs from (1, 0) to (0, 0): x falls along it.
  double previous = 2.0;
  int on_top = 0;
  for (const int id : loop)
    if (set.vertex(id).y == 0.0) {
      EXPECT_LT(set.vertex(id).x, previous);
      previous = set.vertex(id).x;
      ++on_top;
    }
  EXPECT_EQ(on_top, 101);
}

}  // namespace
}  // namespace airlight::geometry
