#include "geometry/beam_tree.hpp"

#include <airlight/error.hpp>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>


// Conditioning, with ε = 10⁻⁶ of the scene's diagonal (beam_epsilon's default) and double
// rounding u ≈ 1.1·10⁻¹⁶:
// - An edge's plane is n = (a' − L) × (b − a), a' the end nearer L: its rounding is u·|a' − L|·
//   |b − a| while |n| = |a' − L|·|b' − L|·sin β, β the angle the edge spans at L, so n errs by
//   about 2u/sin β radians. attach merges corners less than ε apart as seen from L (at the far
//   radius R), so sin β ≥ ε/R = 10⁻⁶ and a plane errs by at most 2·10⁻¹⁰·R within R.
// - A polygon's plane, from its fan's cross products, errs by about u·l/w radians (l its
//   diameter, w = 2·area/l its width); polygons narrower than ε are skipped, so its corners
//   stay within u·l²/ε ≤ 10⁻¹⁰·diagonal of it.
// - Which side of a kept polygon a point light lies on is known: prepare bounds the rounding
//   of its height over the plane (the normal's tilt, about u·l/w, over the distance) and
//   skips the polygon below that.
namespace airlight::geometry {

// A piece's corner. `cut`: the edge to the next corner lies on a plane of the tree that
// bounds the piece's leaf, so attach needs no plane for it.
struct BeamTree::Vertex {
  glm::dvec3 x;
  bool cut = false;
  double tolerance = 0.0;  // beam_tolerance(x): once per corner, not per plane
};

// A convex piece of the input polygon surfaces_[surface].
struct BeamTree::Piece {
  Loop loop;
  int surface = 0;
};

namespace {

// Sets this small are sorted by their own polygons' planes, larger ones by median axis planes
// (while those divide them), which keeps the sort's tree O(log n) deep for spread-out input:
// a convex surface's own planes would make a chain as long as the surface has polygons.
// The sort cut the test's 10⁴-triangle UV sphere into 11858 pieces with 512, 15027 with 128,
// 25034 with 32; its soups alike but less (30737, 31112, 35087).
constexpr size_t kSortLeaf = 512;
constexpr size_t kCandidates = 8;  // planes tried for the fewest cuts
// Sets larger than this are divided into sectors, up to kSectorLevels planes deep (8 sectors):
// enough to keep two cores busy to the end; each sector plane is judged on about
// kSectorSample of the set's pieces.
constexpr size_t kSectorLeaf = 8192;
constexpr int kSectorLevels = 3;
constexpr size_t kSectorSample = 4096;

bool finite(const glm::dvec3& x) { return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z); }

// A polygon's fan from its first corner: twice its area as a vector, how far rounding may
// move that vector (each cross product by about u·|a|·|b|, here 4 ulps) and its diameter.
struct Fan {
  glm::dvec3 twice_area{0.0};
  double rounding = 0.0;
  double diameter = 0.0;

  // 2·area ≤ width·diameter: for a triangle, width is its least height.
  bool narrower_than(double width) const { return glm::length(twice_area) <= width * diameter; }
  // How far the normal may be off by rounding, in radians.
  double tilt() const { return rounding / glm::length(twice_area); }
};

Fan fan_of(std::span<const glm::dvec3> p) {
  Fan fan;
  for (size_t i = 1; i + 1 < p.size(); ++i) {
    const glm::dvec3 a = p[i] - p[0], b = p[i + 1] - p[0];
    fan.twice_area += glm::cross(a, b);
    fan.rounding += 4.0 * std::numeric_limits<double>::epsilon() * glm::length(a) * glm::length(b);
  }
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = i + 1; j < p.size(); ++j) fan.diameter = std::max(fan.diameter, glm::distance(p[i], p[j]));
  return fan;
}

// The corners with each one within `epsilon` of the last kept dropped (the loop closes).
std::vector<glm::dvec3> distinct_corners(const std::vector<glm::dvec3>& vertices, double epsilon) {
  std::vector<glm::dvec3> corners;
  for (const glm::dvec3& v : vertices)
    if (corners.empty() || glm::distance(corners.back(), v) > epsilon) corners.push_back(v);
  while (corners.size() > 1 && glm::distance(corners.back(), corners.front()) <= epsilon) corners.pop_back();
  return corners;
}

glm::dvec3 mean(std::span<const glm::dvec3> p) {
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& x : p) sum += x;
  return sum / static_cast<double>(p.size());
}

double segment_distance(const glm::dvec3& x, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 e = b - a;
  const double t = std::clamp(glm::dot(x - a, e) / glm::dot(e, e), 0.0, 1.0);
  return glm::distance(x, a + t * e);
}

// The distance from x to a convex planar polygon with unit normal n.
double polygon_distance(const glm::dvec3& x, std::span<const glm::dvec3> p, const glm::dvec3& n) {
  const double height = glm::dot(x - p[0], n);
  const glm::dvec3 foot = x - height * n;
  bool inside = true;
  double edge = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < p.size(); ++i) {
    const glm::dvec3& a = p[i];
    const glm::dvec3& b = p[(i + 1) % p.size()];
    inside = inside && glm::dot(glm::cross(b - a, foot - a), n) >= 0.0;
    edge = std::min(edge, segment_distance(x, a, b));
  }
  return inside ? std::abs(height) : edge;
}

}  // namespace

BeamTree::BeamTree(const LightOrigin& light, std::span<const BeamPolygon> polygons, double epsilon)
    : directional_(light.directional),
      light_(light.directional ? glm::normalize(glm::dvec3(light.direction)) : glm::dvec3(light.position)),
      epsilon_(epsilon) {
  if (!(epsilon > 0.0 && std::isfinite(epsilon)))
    throw Failure("beam tree: epsilon must be positive and finite, got " + std::to_string(epsilon));
  add_node(nodes_);  // the root: one open leaf, all of space (§4.1)
  std::vector<Sector> parts;
  sectors(prepare(polygons), 0, kSectorLevels, parts);
  std::vector<Subtree> trees(parts.size());
  tbb::parallel_for(size_t{0}, parts.size(), [&](size_t k) { trees[k] = grow(std::move(parts[k].pieces)); });
  for (size_t k = 0; k < parts.size(); ++k) graft(std::move(trees[k]), parts[k].leaf);
  stats_.depth = depth();
  stats_.sectors = static_cast<int>(parts.size());
}

// A large set is first divided by planes through L (along D) into sectors: each plane is a
// split node at the top of the tree, and as no piece on one side reaches a leaf on the other,
// each sector's tree grows from its own pieces alone, on its own thread, shallower than one
// tree over all. Their leaves are the same pieces' beams as in a tree over all, cut by the
// sector planes too.
void BeamTree::sectors(std::vector<Piece> pieces, int leaf, int levels, std::vector<Sector>& out) {
  const std::optional<Plane> plane = levels > 0 && pieces.size() > kSectorLeaf ? sector_plane(pieces) : std::nullopt;
  if (!plane) return out.push_back({std::move(pieces), leaf});
  const int front = add_node(nodes_), back = add_node(nodes_);
  nodes_[leaf] = {Kind::split, *plane, front, back};
  std::vector<Piece> in_front, behind;
  Scratch scratch;
  for (Piece& piece : pieces) {
    Piece back{{}, piece.surface};
    const Where where = step(piece, *plane, scratch, back);
    if (where == Where::both) behind.push_back(std::move(back));
    (where == Where::back ? behind : in_front).push_back(std::move(piece));
  }
  pieces = {};
  sectors(std::move(in_front), front, levels - 1, out);
  sectors(std::move(behind), back, levels - 1, out);
}

// Of the planes through L (a directional light: along D, through the median of the pieces)
// with a few fixed normals, the one that leaves the fewest pieces on its fuller side (a piece
// it cuts counts on both); none if that is over 3/4 of them. Planes fitted to the pieces'
// directions from L divided toth_hall's sectors evenly but cut a fifth more pieces, which cost
// more in the pyramids than the even division saved (docs/decisions.md).
std::optional<BeamTree::Plane> BeamTree::sector_plane(const std::vector<Piece>& set) const {
  static constexpr double kNormals[13][3] = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1},  {1, 1, 0},  {1, -1, 0},
                                             {1, 0, 1},  {1, 0, -1}, {0, 1, 1},  {0, 1, -1}, {1, 1, 1},
                                             {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
  const size_t stride = std::max<size_t>(1, set.size() / kSectorSample);
  std::optional<Plane> best;
  size_t fullest = std::numeric_limits<size_t>::max(), judged = 0;
  std::vector<double> distance, at;
  for (const auto& a : kNormals) {
    glm::dvec3 n = glm::normalize(glm::dvec3(a[0], a[1], a[2]));
    if (directional_) n -= glm::dot(n, light_) * light_;
    if (glm::length(n) < 0.5) continue;  // nearly along D
    Plane plane{glm::normalize(n), -glm::dot(glm::normalize(n), light_)};
    if (directional_) {
      at.clear();
      for (size_t k = 0; k < set.size(); k += stride) at.push_back(glm::dot(plane.n, set[k].loop.front().x));
      std::nth_element(at.begin(), at.begin() + at.size() / 2, at.end());
      plane.d = -at[at.size() / 2];
    }
    size_t front = 0, back = 0;
    judged = 0;
    for (size_t k = 0; k < set.size(); k += stride, ++judged) {
      const Where where = sides(set[k].loop, plane, true, distance);
      front += where != Where::back;
      back += where == Where::back || where == Where::both;
    }
    if (std::max(front, back) < fullest) std::tie(best, fullest) = std::pair(plane, std::max(front, back));
  }
  return 4 * fullest <= 3 * judged ? best : std::nullopt;
}

// The sector's pieces in front-to-back order, inserted into a tree of their own.
BeamTree::Subtree BeamTree::grow(std::vector<Piece> pieces) const {
  Subtree tree;
  std::vector<Piece> order = sort_front_to_back(std::move(pieces));
  tree.sorted_pieces = static_cast<int>(order.size());
  add_node(tree.nodes);
  Scratch scratch;
  for (Piece& piece : order) insert(std::move(piece), scratch, tree);
  return tree;
}

// The subtree in place of the open leaf: its root there, its other nodes appended.
void BeamTree::graft(Subtree tree, int leaf) {
  const int offset = static_cast<int>(nodes_.size()) - 1;  // node k ≥ 1 goes to k + offset
  for (size_t k = 0; k < tree.nodes.size(); ++k) {
    Node node = tree.nodes[k];
    if (node.kind == Kind::split) node.front += offset, node.back += offset;
    if (k == 0) nodes_[leaf] = node;
    else nodes_.push_back(node);
  }
  visible_.insert(visible_.end(), std::make_move_iterator(tree.visible.begin()), std::make_move_iterator(tree.visible.end()));
  stats_.sorted_pieces += tree.sorted_pieces;
  stats_.thin_pieces += tree.thin_pieces;
}

std::vector<BeamTree::Piece> BeamTree::prepare(std::span<const BeamPolygon> polygons) {
  for (size_t k = 0; k < polygons.size(); ++k)
    for (const glm::dvec3& v : polygons[k].vertices) {
      if (!finite(v)) throw Failure("beam tree: polygon " + std::to_string(k) + " has a non-finite vertex");
      if (!directional_) far_ = std::max(far_, glm::distance(v, light_));
    }
  std::vector<Piece> pieces;
  for (size_t k = 0; k < polygons.size(); ++k) admit(polygons[k], k, pieces);
  return pieces;
}

// Appends the polygon as a piece with its surface, or counts it as skipped (header).
void BeamTree::admit(const BeamPolygon& polygon, size_t index, std::vector<Piece>& pieces) {
  const std::vector<glm::dvec3> corners = distinct_corners(polygon.vertices, epsilon_);
  const Fan fan = fan_of(corners);
  if (corners.size() < 3 || fan.narrower_than(epsilon_)) {
    ++stats_.zero_area;
    return;
  }
  const glm::dvec3 n = glm::normalize(fan.twice_area), centre = mean(corners);
  const Plane plane{n, -glm::dot(n, centre)};
  for (const glm::dvec3& v : corners)  // ε plus what the normal's rounding tilts the plane by
    if (std::abs(plane.distance(v)) > epsilon_ + fan.tilt() * glm::distance(v, centre))
      throw Failure("beam tree: polygon " + std::to_string(index) + " is not planar within epsilon");
  // How far rounding may move a point light's height over the plane: the normal's tilt over
  // the distance to the centre, and the sum's own rounding.
  const double rounding = fan.tilt() * glm::distance(light_, centre) +
                          4.0 * std::numeric_limits<double>::epsilon() * (glm::length(light_) + glm::length(centre));
  if (edge_on(corners, plane, rounding)) {
    ++stats_.edge_on;
    return;
  }
  const bool faces_light = directional_ ? glm::dot(n, light_) < 0.0 : plane.distance(light_) > 0.0;
  surfaces_.push_back({faces_light ? plane : Plane{-plane.n, -plane.d}, faces_light, polygon.source});
  Piece& piece = pieces.emplace_back();
  piece.surface = static_cast<int>(surfaces_.size() - 1);
  for (const glm::dvec3& v : corners) piece.loop.push_back(vertex(v, false));
}

// Whether the polygon's shadow is at most ε thick within R: seen along D, the polygon is
// narrower than ε (then |n·D| ≥ ε/diameter, far above its rounding); seen from a point light
// at height h over its plane, a part at distance r spans an angle of about |h|/r across,
// R·|h|/r at the far radius, widest at the polygon's nearest point. Skipped too: polygons
// within ε of a point light, which side of them it lights being below the tolerance, and
// those whose h is within its rounding (a sliver nearly edge-on near the light), on which
// every edge's orientation depends.
bool BeamTree::edge_on(std::span<const glm::dvec3> corners, const Plane& plane, double rounding) const {
  if (!directional_) {
    const double nearest = polygon_distance(light_, corners, plane.n), height = std::abs(plane.distance(light_));
    return nearest <= epsilon_ || height <= rounding || far_ * height <= epsilon_ * nearest;
  }
  std::vector<glm::dvec3> seen;
  for (const glm::dvec3& v : corners) seen.push_back(v - glm::dot(v, light_) * light_);
  return fan_of(seen).narrower_than(epsilon_);
}

// A BSP sort (ch. 6's remedy): each set is divided by a plane into the side holding L, the
// pieces in the plane and the far side, which go out in that order; nothing on the far side
// can hide anything on the near side or in the plane. The first division's two sides are
// sorted on two threads (the order is the same as on one).
std::vector<BeamTree::Piece> BeamTree::sort_front_to_back(std::vector<Piece> pieces) const {
  if (pieces.size() <= kSortLeaf) return sort_set(std::move(pieces));
  std::vector<Piece> near, on, far;
  divide(pieces, near, on, far);
  pieces = {};
  tbb::parallel_invoke([&] { near = sort_set(std::move(near)); }, [&] { far = sort_set(std::move(far)); });
  for (std::vector<Piece>* part : {&on, &far})
    near.insert(near.end(), std::make_move_iterator(part->begin()), std::make_move_iterator(part->end()));
  return near;
}

// The sort of one set, with explicit stacks: no recursion depth.
std::vector<BeamTree::Piece> BeamTree::sort_set(std::vector<Piece> pieces) const {
  struct Task {
    std::vector<Piece> set;
    bool in_order;  // the pieces of one plane: none hides another
  };
  std::vector<Task> tasks;
  tasks.push_back({std::move(pieces), false});
  std::vector<Piece> order;
  while (!tasks.empty()) {
    Task task = std::move(tasks.back());
    tasks.pop_back();
    if (task.in_order || task.set.size() <= 1) {
      for (Piece& piece : task.set) order.push_back(std::move(piece));
      continue;
    }
    std::vector<Piece> near, on, far;
    divide(task.set, near, on, far);
    tasks.push_back({std::move(far), false});
    tasks.push_back({std::move(on), true});
    tasks.push_back({std::move(near), false});
  }
  return order;
}

// Moves the set's pieces (and the parts of those the plane cuts) to its sides.
void BeamTree::divide(std::vector<Piece>& set, std::vector<Piece>& near, std::vector<Piece>& on,
                      std::vector<Piece>& far) const {
  if (set.size() > kSortLeaf) {
    const Plane median = median_plane(set);
    if (divides(set, median)) return separate(set, median, near, on, far);
  }
  // A piece lies in its own plane, so each such step places at least one piece.
  separate(set, fewest_cuts(set), near, on, far);
}

// Whether each side of the plane gets fewer pieces than the set (a piece it cuts goes to both).
bool BeamTree::divides(const std::vector<Piece>& set, const Plane& plane) const {
  size_t front = 0, back = 0;
  std::vector<double> distance;
  for (const Piece& piece : set) {
    const Where where = sides(piece.loop, plane, false, distance);
    front += where == Where::front || where == Where::both;
    back += where == Where::back || where == Where::both;
  }
  return front < set.size() && back < set.size();
}

// Of a few pieces' planes spread over the set, the one that cuts the fewest pieces: cuts
// make more pieces, and each piece's edges become planes of the beam tree.
BeamTree::Plane BeamTree::fewest_cuts(const std::vector<Piece>& set) const {
  Plane best;
  size_t fewest = std::numeric_limits<size_t>::max();
  std::vector<double> distance;
  const size_t step = std::max<size_t>(1, set.size() / kCandidates);
  for (size_t k = 0; k < set.size() && fewest > 0; k += step) {
    const Plane& plane = surfaces_[set[k].surface].plane;
    size_t cuts = 0;
    for (const Piece& piece : set) cuts += sides(piece.loop, plane, false, distance) == Where::both;
    if (cuts < fewest) std::tie(best, fewest) = std::pair(plane, cuts);
  }
  return best;
}

// The axis plane through the median of the pieces' centroids along their widest axis.
BeamTree::Plane BeamTree::median_plane(const std::vector<Piece>& set) const {
  std::vector<glm::dvec3> centroids;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Piece& piece : set) {
    glm::dvec3 sum(0.0);
    for (const Vertex& v : piece.loop) sum += v.x;
    centroids.push_back(sum / static_cast<double>(piece.loop.size()));
    lo = glm::min(lo, centroids.back());
    hi = glm::max(hi, centroids.back());
  }
  const glm::dvec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  std::vector<double> at;
  for (const glm::dvec3& c : centroids) at.push_back(c[axis]);
  const auto middle = at.begin() + static_cast<std::ptrdiff_t>(at.size() / 2);
  std::nth_element(at.begin(), middle, at.end());
  glm::dvec3 n(0.0);
  n[axis] = 1.0;
  return {n, -*middle};
}

void BeamTree::separate(std::vector<Piece>& set, const Plane& plane, std::vector<Piece>& near,
                        std::vector<Piece>& on, std::vector<Piece>& far) const {
  // The side holding L (directional: the side the light comes from); a plane through L or
  // along D has no such side, and then neither side hides the other.
  const bool front_near = directional_ ? glm::dot(plane.n, light_) <= 0.0 : plane.distance(light_) >= 0.0;
  std::vector<Piece>& front = front_near ? near : far;
  std::vector<Piece>& back = front_near ? far : near;
  std::vector<double> distance;
  for (Piece& piece : set) switch (sides(piece.loop, plane, false, distance)) {
      case Where::front: front.push_back(std::move(piece)); break;
      case Where::back: back.push_back(std::move(piece)); break;
      case Where::on: on.push_back(std::move(piece)); break;
      case Where::both:
        clip(piece.loop, distance, 1, false, front.emplace_back(Piece{{}, piece.surface}).loop);
        clip(piece.loop, distance, -1, false, back.emplace_back(Piece{{}, piece.surface}).loop);
        break;
    }
}

// Programs 3 and 4, without recursion: a piece reaching a solid leaf is in shadow; one
// reaching an open leaf is seen from L.
void BeamTree::insert(Piece piece, Scratch& scratch, Subtree& tree) const {
  std::vector<std::pair<int, Piece>>& stack = scratch.stack;
  stack.emplace_back(0, std::move(piece));
  while (!stack.empty()) {
    auto [index, part] = std::move(stack.back());
    stack.pop_back();
    for (;;) {  // down the front, the back part of each cut left on the stack
      const Node& node = tree.nodes[index];
      if (node.kind == Kind::solid) break;
      if (node.kind == Kind::open) {  // after attach, `node` may be gone: it grows the nodes
        attach(index, part, tree);
        break;
      }
      Piece back{{}, part.surface};
      const Where where = step(part, node.plane, scratch, back);
      if (where == Where::both) stack.emplace_back(node.back, std::move(back));
      index = where == Where::back ? node.back : node.front;
    }
  }
}

// One split node's step: whether the piece goes in front (Program 2's side where it lies in
// the plane), behind or to both, its edges along the plane marked; a piece cut in two keeps
// its front part and gives its back part to `back`.
BeamTree::Where BeamTree::step(Piece& piece, const Plane& plane, Scratch& scratch, Piece& back) const {
  const Where where = sides(piece.loop, plane, true, scratch.distance);
  if (where == Where::front || where == Where::back) mark_cuts(piece.loop, scratch.distance);
  if (where != Where::both) return where;
  clip(piece.loop, scratch.distance, -1, true, back.loop);
  clip(piece.loop, scratch.distance, 1, true, scratch.loop);
  std::swap(piece.loop, scratch.loop);
  return where;
}

// Program 4: the open leaf becomes the chain of the planes through L and the piece's edges,
// each with an open leaf in front, ending in a solid leaf with the piece's plane. (Program 4
// stores solidPlane on the last split node, not on the solid leaf that needs it.)
void BeamTree::attach(int leaf, const Piece& piece, Subtree& tree) const {
  const Loop corners = outline(piece.loop);
  if (corners.size() < 3) {
    ++tree.thin_pieces;
    return;
  }
  const Surface& surface = surfaces_[piece.surface];
  int node = leaf;
  for (size_t i = 0; i < corners.size(); ++i) {
    if (corners[i].cut) continue;
    const Plane plane = edge_plane(corners[i].x, corners[(i + 1) % corners.size()].x, surface.faces_light);
    const int front = add_node(tree.nodes), back = add_node(tree.nodes);
    tree.nodes[node] = {Kind::split, plane, front, back};
    node = back;
  }
  tree.nodes[node] = {Kind::solid, surface.plane, -1, -1};
  BeamPolygon& seen = tree.visible.emplace_back();
  seen.source = surface.source;
  for (const Vertex& v : piece.loop) seen.vertices.push_back(v.x);
}

// The loop with each corner less than ε from the last kept one, as seen from L (point light:
// on the sphere of radius R about L; directional: across D), dropped: the kept corner's edge
// now runs where the dropped one's did, within ε as seen from L, and takes its `cut`. At the
// loop's end the last corners, close to the first, are dropped with their short edges.
BeamTree::Loop BeamTree::outline(const Loop& loop) const {
  const auto seen = [&](const glm::dvec3& x) {
    return directional_ ? x - glm::dot(x, light_) * light_ : far_ * glm::normalize(x - light_);
  };
  const auto close = [&](const Vertex& a, const Vertex& b) { return glm::distance(seen(a.x), seen(b.x)) < epsilon_; };
  Loop corners;
  for (const Vertex& v : loop) {
    if (corners.empty() || !close(corners.back(), v)) corners.push_back(v);
    else corners.back().cut = v.cut;
  }
  while (corners.size() > 1 && close(corners.back(), corners.front())) corners.pop_back();
  return corners;
}

// The plane through L (or along D) and the edge a → b, the piece behind it. (a − L) × (b − a)
// = (b − L) × (b − a) = (a − L) × (b − L); the arm from the nearer end rounds least (top of file).
BeamTree::Plane BeamTree::edge_plane(const glm::dvec3& a, const glm::dvec3& b, bool faces_light) const {
  glm::dvec3 n;
  if (directional_) {
    n = glm::cross(light_, b - a);
  } else {
    const glm::dvec3& nearer = glm::distance(a, light_) <= glm::distance(b, light_) ? a : b;
    n = glm::cross(nearer - light_, b - a);
  }
  n = glm::normalize(faces_light ? n : -n);
  return {n, -glm::dot(n, directional_ ? a : light_)};
}

int BeamTree::add_node(std::vector<Node>& nodes) {
  nodes.emplace_back();
  return static_cast<int>(nodes.size() - 1);
}

int BeamTree::depth() const {
  int deepest = 0;
  std::vector<std::pair<int, int>> stack{{0, 1}};
  while (!stack.empty()) {
    const auto [index, level] = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, level);
    const Node& node = nodes_[index];
    if (node.kind != Kind::split) continue;
    stack.emplace_back(node.front, level + 1);
    stack.emplace_back(node.back, level + 1);
  }
  return deepest;
}

// Which sides of the plane the loop has corners on, a corner within tolerance counting as in
// the plane (its distance set to 0). `beam`: a plane through L, with beam_tolerance.
BeamTree::Where BeamTree::sides(const Loop& loop, const Plane& plane, bool beam,
                                std::vector<double>& distance) const {
  distance.resize(loop.size());
  bool front = false, back = false;
  for (size_t i = 0; i < loop.size(); ++i) {
    const double d = plane.distance(loop[i].x);
    const double tolerance = beam ? loop[i].tolerance : epsilon_;
    distance[i] = std::abs(d) <= tolerance ? 0.0 : d;
    front = front || distance[i] > 0.0;
    back = back || distance[i] < 0.0;
  }
  return front && back ? Where::both : front ? Where::front : back ? Where::back : Where::on;
}

// Sutherland–Hodgman: the part of a convex loop on `side` (+1 front, −1 back) of the plane,
// given sides' distances; corners in the plane belong to both parts. An edge of the part
// that is a piece of an edge of the loop keeps its `cut`; one along the plane gets `cut`.
void BeamTree::clip(const Loop& in, const std::vector<double>& distance, int side, bool cut, Loop& out) const {
  out.clear();
  for (size_t i = 0; i < in.size(); ++i) {
    const size_t j = (i + 1) % in.size();
    const double di = side * distance[i], dj = side * distance[j];
    if (di >= 0.0)
      out.push_back({in[i].x, di > 0.0 || dj > 0.0 ? in[i].cut : (dj == 0.0 && in[i].cut) || cut, in[i].tolerance});
    if (di * dj < 0.0)
      out.push_back(vertex(in[i].x + distance[i] / (distance[i] - distance[j]) * (in[j].x - in[i].x),
                           dj > 0.0 ? in[i].cut : cut));
  }
}

BeamTree::Vertex BeamTree::vertex(const glm::dvec3& x, bool cut) const {
  return {x, cut, beam_tolerance(x)};
}

// Edges of a loop on one side of a plane whose both ends lie in it (distance 0 from sides)
// run along the plane, which bounds the leaf already: a plane through them again would leave
// an open leaf between the two, empty but for points in both ε bands.
void BeamTree::mark_cuts(Loop& loop, const std::vector<double>& distance) {
  for (size_t i = 0; i < loop.size(); ++i)
    if (distance[i] == 0.0 && distance[(i + 1) % loop.size()] == 0.0) loop[i].cut = true;
}

// Point lights: ε at the far radius R, in proportion to the distance from L (header).
double BeamTree::beam_tolerance(const glm::dvec3& x) const {
  return directional_ ? epsilon_ : epsilon_ * glm::distance(x, light_) / far_;
}

// Program 2 with both sides of a thick plane.
BeamTree::Side BeamTree::classify(const glm::dvec3& p) const {
  bool lit = false, shadowed = false;
  std::vector<int> stack{0};
  while (!stack.empty() && !(lit && shadowed)) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    const double d = node.plane.distance(p);
    switch (node.kind) {
      case Kind::open: lit = true; break;
      case Kind::solid:
        lit = lit || d >= -epsilon_;
        shadowed = shadowed || d <= epsilon_;
        break;
      case Kind::split:
        if (d >= -epsilon_) stack.push_back(node.front);
        if (d <= epsilon_) stack.push_back(node.back);
        break;
    }
  }
  return lit && shadowed ? Side::boundary : lit ? Side::lit : Side::shadowed;
}

// Program 5: parts in open leaves are lit; a part in a solid leaf is cut by the leaf's plane
// into the lit part in front and the shadowed part behind. Parts within tolerance of a plane
// go to its front, as when building.
void BeamTree::partition(const BeamPolygon& polygon, std::vector<BeamPolygon>& lit,
                         std::vector<BeamPolygon>& shadowed) const {
  if (polygon.vertices.size() < 3) return;
  const auto emit = [&](std::vector<BeamPolygon>& out, const Loop& loop) {
    BeamPolygon& part = out.emplace_back();
    part.source = polygon.source;
    for (const Vertex& v : loop) part.vertices.push_back(v.x);
  };
  std::vector<std::pair<int, Loop>> stack(1);
  for (const glm::dvec3& v : polygon.vertices) stack[0].second.push_back(vertex(v, false));
  std::vector<double> distance;
  while (!stack.empty()) {
    auto [index, loop] = std::move(stack.back());
    stack.pop_back();
    const Node& node = nodes_[index];
    if (node.kind == Kind::open) {
      emit(lit, loop);
      continue;
    }
    const Where where = sides(loop, node.plane, node.kind == Kind::split, distance);
    Loop front, back;
    if (where == Where::both) {
      clip(loop, distance, 1, false, front);
      clip(loop, distance, -1, false, back);
    } else {
      (where == Where::back ? back : front) = std::move(loop);
    }
    if (node.kind == Kind::solid) {
      if (!front.empty()) emit(lit, front);
      if (!back.empty()) emit(shadowed, back);
      continue;
    }
    if (!front.empty()) stack.emplace_back(node.front, std::move(front));
    if (!back.empty()) stack.emplace_back(node.back, std::move(back));
  }
}

double beam_epsilon(const LightOrigin& light, std::span<const BeamPolygon> polygons, double relative) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi = -lo;
  const auto grow = [&](const glm::dvec3& x) {
    lo = glm::min(lo, x);
    hi = glm::max(hi, x);
  };
  if (!light.directional) grow(glm::dvec3(light.position));
  for (const BeamPolygon& polygon : polygons)
    for (const glm::dvec3& v : polygon.vertices) grow(v);
  const double diagonal = lo.x <= hi.x ? glm::distance(lo, hi) : 0.0;
  return relative * (diagonal > 0.0 ? diagonal : 1.0);
}

}  // namespace airlight::geometry
