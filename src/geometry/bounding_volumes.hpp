#pragma once
// Bounding volumes (Nilsson 2008 §5.1–5.2): each object gets an outer convex volume that
// encloses it and, when it has an inside, an inner convex volume inside it. Per light, the
// beam tree of the outer volumes' faces bounds what any object can shadow, and the beam tree
// of the inner volumes' faces (his stopper polygons and blocker leaves) what some object
// surely shadows; every point, and every part of a polygon, is then fully lit, uncertain or
// unlit (§5.2.1), and only the uncertain parts need the objects' own triangles.
#include "geometry/beam_tree.hpp"
#include "geometry/shadow_edges.hpp"

#include <airlight/box.hpp>
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <span>
#include <vector>

namespace airlight::geometry {

struct BoundingVolumes {
  OrientedBox outer;                 // encloses every vertex
  std::optional<OrientedBox> inner;  // inside the closed mesh; none without an inside
};

// The mesh's outer_box and inner_box when the scene gives them; otherwise the outer volume is
// the world-space axis-aligned box of its vertices (not the convex hull: six faces keep the
// beam tree small, and Nilsson's volumes are boxes too), and the inner one, for a mesh closed
// once welded by exact position, the largest copy of that box scaled about the mean of its
// vertices that lies inside it (solid::box_inside), the scale found by 20 bisections below
// the largest that keeps the copy inside the outer box: the box itself, nearly, for a box, the
// inscribed cube of a sphere; none when the mean is outside or the mesh is open. (A cube, as
// first built, left a thin slab a sliver of its inside.)
BoundingVolumes bounding_volumes(const Mesh& mesh);

// The box's six faces as beam tree polygons, each with `source`.
std::vector<BeamPolygon> box_faces(const OrientedBox& box, int source);

// One light's regions (§5.2.1) among the volumes of the objects that cast shadows; a
// polygon's source is its volumes' index in the span.
class LightRegions {
public:
  enum class Region { fully_lit, uncertain, unlit };

  // ε is beam_epsilon of the outer faces. A point light inside an object's outer volume may be
  // inside the object, where its inner volume proves nothing: that inner volume is left out,
  // and no region is fully lit.
  LightRegions(const LightOrigin& light, std::span<const BoundingVolumes> volumes);

  // fully_lit: lit in the outer tree, so no object lies between p and the light; unlit:
  // shadowed in the inner tree, so the path enters an inner volume, hence crosses its object's
  // surface first; uncertain otherwise, within ε of either tree's planes included.
  Region classify(const glm::dvec3& p) const;

  // Appends the parts of a convex polygon of each region: BeamTree::partition by the outer
  // tree, then its shadowed parts by the inner tree. Each part keeps the polygon's source.
  void partition(const BeamPolygon& polygon, std::vector<BeamPolygon>& fully_lit,
                 std::vector<BeamPolygon>& uncertain, std::vector<BeamPolygon>& unlit) const;

  double epsilon() const { return epsilon_; }
  const BeamTree& outer() const { return outer_; }
  const BeamTree& inner() const { return inner_; }

private:
  LightRegions(const LightOrigin& light, const std::vector<BeamPolygon>& outer_faces,
               const std::vector<BeamPolygon>& inner_faces, bool surrounded);

  double epsilon_;
  // A point light inside an object's outer volume: the outer tree's lit side
  // then includes the box around the light, where the object may stand between
  // a point and the light, so nothing is proved fully lit.
  bool surrounded_;
  BeamTree outer_, inner_;
};

}  // namespace airlight::geometry
