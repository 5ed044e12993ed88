#pragma once
// Nilsson 2008 §3.2 and ch. 4: per light, the beam tree of every caster's
// triangles (geometry/beam_tree.hpp) and its visible set — the polygons the
// light sees first, the influence volume's backplate included — as the
// pyramids (prisms for a directional light) between the light and each of
// them: together, exactly the light's lit region. Their faces are the
// triangles the kit's lit-interval pass counts.
#include "geometry/beam_tree.hpp"
#include "geometry/conforming_set.hpp"
#include "methods/kit/counting/crossing_geometry.hpp"

namespace airlight::methods {

class LitPyramids final : public kit::CasterCrossings {
public:
  // beam_tree_nodes, visible_polygons, pyramid_faces, build_s.
  std::vector<std::pair<std::string, double>> stats() const override;

private:
  // The casters' triangles, in object space: copied, so that the caller need
  // not keep the scene after prepare() (docs/design.md §3).
  void prepare_casters(const Scene& scene, const std::vector<int>& casters) override;
  // The frame's beam trees and pyramids, and each light's count at the eye: 0
  // where the eye is lit, 1 where not.
  void add_triangles(const FrameInputs& inputs) override;
  std::vector<geometry::BeamPolygon> world_polygons(const FrameInputs& inputs) const;
  void add_pyramids(const geometry::ConformingSet& set, const Light& light, int index, double reach, double epsilon);
  void add_face(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, int index, int weight);

  struct Caster {
    int mesh;  // index into Scene::meshes (and FrameInputs::transforms)
    std::vector<glm::vec3> positions;
    std::vector<glm::uvec3> triangles;
  };
  std::vector<Caster> casters_;
  int nodes_ = 0, visible_ = 0;
};

}  // namespace airlight::methods
