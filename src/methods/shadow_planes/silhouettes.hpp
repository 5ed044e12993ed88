#pragma once
// The shadow planes of every caster and light for one frame (Biri §5.1): each
// caster welded with its edges' triangles once per scene, and per frame the
// edges whose weight is not 0 (geometry/shadow_edges.hpp) extruded away from
// their light to infinity, as the triangles the kit's lit-interval pass counts;
// and the casters' own triangles where a view ray may cross them before it
// reaches the near plane (add_caps).
#include "geometry/shadow_edges.hpp"
#include "methods/kit/counting/crossing_geometry.hpp"

namespace airlight::methods {

class Silhouettes final : public kit::CasterCrossings {
public:
  // The frame's planes and eye counts, then the loops the report counts.
  void build(const kit::SceneFrame& frame, gpu::PassTimer& timer) override;

  // Counters for the report: caster triangles, planes, silhouette and
  // boundary edges, loops, build_s, and per caster whether it is closed (its
  // planes are its silhouette) or open (the edges of its triangles' own volumes).
  std::vector<std::pair<std::string, double>> stats() const override;

private:
  // Welds each caster and finds its edges' triangles.
  void prepare_casters(const Scene& scene, const std::vector<int>& casters) override;
  // The frame's planes and each light's count at the eye.
  void add_triangles(const FrameInputs& inputs) override;
  struct Caster {
    int mesh = 0;
    geometry::CasterTopology topology;
    std::vector<glm::vec3> world;  // this frame's welded positions
  };
  void move_casters(const FrameInputs& inputs);
  void add_planes(const std::vector<geometry::ShadowPlane>& planes, const Light& light, int index);
  void add_caps(const Caster& caster, const glm::dvec3& eye, double reach, const geometry::LightOrigin& light,
                int index);
  int count_at(const geometry::LightOrigin& light, const glm::vec3& p) const;

  std::vector<Caster> casters_;
  std::vector<geometry::ShadowPlane> planes_;  // of one light, reused
  int plane_count_ = 0, silhouette_edges_ = 0, boundary_edges_ = 0, loops_ = 0;
};

}  // namespace airlight::methods
