#pragma once
// The Beam Tree (Nilsson 2008, ch. 4 and appendix B): a solid BSP tree whose splitting planes
// all pass through the light L (a directional light travelling along D: planes parallel to D),
// built from polygons, that answers "is p lit from L?", splits polygons into their lit and
// shadowed parts (§4.4) and gives the visible set: the polygon pieces seen from L (§3.2.1).
//
// Leaves are open (lit: the beam meets no polygon) or solid: the beam behind one piece of the
// visible set, whose plane the leaf keeps (Program 4's solidPlane). A point in a solid leaf is
// lit in front of that plane and shadowed behind it; Program 2 calls the whole leaf solid,
// which is wrong in front of the piece (Program 5 partitions as here).
//
// Construction. The polygons are sorted front to back from L by a BSP tree over them (the
// remedy ch. 6 names for its own restriction to sorted, non-intersecting input): median
// splits by axis planes while a set is large, the polygons' own planes below that; each
// plane's side holding L comes first, then what lies in the plane, then the far side. So
// any input order works, and polygons that cross or overlap are cut where needed. The pieces
// are then inserted in that order (Program 3): a piece reaching an open leaf becomes visible
// and the leaf becomes the chain of the planes through L and its edges, ending in a solid
// leaf with its plane (Program 4); pieces reaching solid leaves are dropped (in shadow). An
// edge that lies on a plane of the tree already bounds the leaf and adds no plane. A large
// set is first divided by a few planes through L (along D) into sectors, split nodes at the
// top of the tree: no piece crosses to another sector's leaves, so each sector is sorted and
// inserted on its own, in parallel.
//
// Tolerances (§4.3, ε the caller's, e.g. beam_epsilon). A point within ε of a splitting plane
// goes down both sides (Program 2 sends it to the front only); a solid leaf's plane is ε thick
// too. While building, a plane through a point light is ε thick at the far radius R (the
// farthest input vertex from L) and thinner toward L, ε·|x − L|/R: a piece's overhang past a
// plane spreads along its beam in proportion to the distance from L, so this bounds the tree's
// error at any p within R by ε·|p − L|/R ≤ ε (beyond R it grows so). Planes parallel to D,
// polygon planes and the sort's planes are ε thick everywhere.
//
// Degenerate input is skipped and counted (BeamTreeStats): polygons narrower than ε
// (repeated or collinear vertices, slivers: twice the area over the diameter ≤ ε); polygons
// edge-on to the light, whose shadow is at most ε thick within R (the same measure of their
// cross-section seen along D, or from L scaled to R); polygons within ε of a point light, or
// whose side of it is below their plane's rounding. A point only a skipped polygon would
// shadow lies within ε·|p − L|/R of one of its beam's planes, or its path to L passes within
// ε of L. Non-finite polygons, and polygons with a corner farther than ε (plus rounding)
// from their plane, throw airlight::Failure.
//
// The caller includes the backplate of the light's influence (influence_backplate.hpp) among the
// polygons, so that every beam ends on a piece of the visible set (§3.2.1).
#include "geometry/shadow_edges.hpp"

#include <airlight/scene.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <vector>

namespace airlight::geometry {

// A convex planar polygon, its vertices in order around it (either winding).
struct BeamPolygon {
  std::vector<glm::dvec3> vertices;
  int source = -1;  // the caller's id, kept by every piece cut from it; -1: the backplate
};

struct BeamTreeStats {
  int zero_area = 0;         // input polygons skipped: narrower than ε
  int edge_on = 0;           // input polygons skipped: edge-on to the light within ε
  int sorted_pieces = 0;     // pieces the BSP sort cut the rest into
  int thin_pieces = 0;       // pieces narrower than ε seen from L that reached an open leaf:
                             // dropped, the leaf left open for what lies behind
  int depth = 0;             // nodes on the longest path from the root to a leaf
  int sectors = 0;           // the trees grown apart below the sector planes (1: none)
};

class BeamTree {
public:
  // Polygons in any order; epsilon > 0 (throws airlight::Failure otherwise).
  BeamTree(const LightOrigin& light, std::span<const BeamPolygon> polygons, double epsilon);

  // Program 2 with thick planes. boundary: p lies within ε of a plane whose two sides answer
  // differently, the plane of a visible piece included (a point on a lit surface is on the
  // boundary).
  enum class Side { lit, shadowed, boundary };
  Side classify(const glm::dvec3& p) const;

  // Appends the parts of a convex polygon in front of the visible set to `lit` and those
  // behind it to `shadowed` (§4.4, Program 5), each with the polygon's source.
  void partition(const BeamPolygon& polygon, std::vector<BeamPolygon>& lit,
                 std::vector<BeamPolygon>& shadowed) const;

  // The pieces of the polygons seen from L, each with its polygon's source: cut by the sort's
  // and the tree's planes, so many pieces to a polygon; they do not overlap as seen from L.
  const std::vector<BeamPolygon>& visible_set() const { return visible_; }
  int node_count() const { return static_cast<int>(nodes_.size()); }
  const BeamTreeStats& stats() const { return stats_; }

private:
  struct Plane {
    glm::dvec3 n{0.0};  // unit
    double d = 0.0;
    double distance(const glm::dvec3& x) const { return glm::dot(n, x) + d; }
  };
  enum class Kind : unsigned char { split, open, solid };
  struct Node {
    Kind kind = Kind::open;
    Plane plane;  // split: through L, the leaf's outside in front; solid: the piece's, L in front
    int front = -1, back = -1;
  };
  struct Surface {     // an input polygon kept
    Plane plane;       // L in front
    bool faces_light;  // its vertices wind counter-clockwise seen from L
    int source;
  };
  struct Vertex;
  struct Piece;
  using Loop = std::vector<Vertex>;
  enum class Where : unsigned char { front, back, on, both };

  // A tree over one sector's pieces, built on its own thread: its root (index 0) fills the
  // sector's open leaf of nodes_, the rest are appended.
  struct Subtree {
    std::vector<Node> nodes;
    std::vector<BeamPolygon> visible;
    int sorted_pieces = 0, thin_pieces = 0;
  };
  struct Scratch {  // an insertion's buffers, kept from piece to piece
    std::vector<double> distance;
    Loop loop;
    std::vector<std::pair<int, Piece>> stack;
  };
  struct Sector {
    std::vector<Piece> pieces;
    int leaf;  // the open leaf of nodes_ they go down to
  };

  std::vector<Piece> prepare(std::span<const BeamPolygon> polygons);
  void admit(const BeamPolygon& polygon, size_t index, std::vector<Piece>& pieces);
  bool edge_on(std::span<const glm::dvec3> corners, const Plane& plane, double rounding) const;
  std::vector<Piece> sort_front_to_back(std::vector<Piece> pieces) const;
  std::vector<Piece> sort_set(std::vector<Piece> pieces) const;
  void divide(std::vector<Piece>& set, std::vector<Piece>& near, std::vector<Piece>& on,
              std::vector<Piece>& far) const;
  bool divides(const std::vector<Piece>& set, const Plane& plane) const;
  Plane median_plane(const std::vector<Piece>& set) const;
  Plane fewest_cuts(const std::vector<Piece>& set) const;
  void separate(std::vector<Piece>& set, const Plane& plane, std::vector<Piece>& near,
                std::vector<Piece>& on, std::vector<Piece>& far) const;
  void sectors(std::vector<Piece> pieces, int leaf, int levels, std::vector<Sector>& out);
  std::optional<Plane> sector_plane(const std::vector<Piece>& set) const;
  Where step(Piece& piece, const Plane& plane, Scratch& scratch, Piece& back) const;
  Subtree grow(std::vector<Piece> pieces) const;
  void graft(Subtree tree, int leaf);
  void insert(Piece piece, Scratch& scratch, Subtree& tree) const;
  void attach(int leaf, const Piece& piece, Subtree& tree) const;
  Loop outline(const Loop& loop) const;
  Plane edge_plane(const glm::dvec3& a, const glm::dvec3& b, bool faces_light) const;
  static int add_node(std::vector<Node>& nodes);
  int depth() const;

  Where sides(const Loop& loop, const Plane& plane, bool beam, std::vector<double>& distance) const;
  static void mark_cuts(Loop& loop, const std::vector<double>& distance);
  void clip(const Loop& in, const std::vector<double>& distance, int side, bool cut, Loop& out) const;
  Vertex vertex(const glm::dvec3& x, bool cut) const;
  double beam_tolerance(const glm::dvec3& x) const;

  bool directional_;
  glm::dvec3 light_;  // the position of a point light, the unit direction of a directional one
  double epsilon_;
  double far_ = 0.0;  // R: the farthest input vertex from a point light
  std::vector<Surface> surfaces_;
  std::vector<Node> nodes_;
  std::vector<BeamPolygon> visible_;
  BeamTreeStats stats_;
};

// ε for a tree of these polygons and this light: `relative` times the diagonal of the box
// around their vertices (and a point light's position), or `relative` metres when that box
// is a point. The default leaves ε 10¹⁰ times above double rounding at the scene's scale
// and far below anything visible (Nilsson suggests 1 mm for scenes in metres); see
// beam_tree.cpp for the conditioning it buys.
double beam_epsilon(const LightOrigin& light, std::span<const BeamPolygon> polygons,
                    double relative = 1e-6);

}  // namespace airlight::geometry
