#pragma once
// Nilsson 2008 §5.3–5.4: the virtual planes cut into pieces by each light's
// regions of space. Per frame and light, the beam trees of the casters'
// bounding volumes (geometry::LightRegions: fully lit, uncertain, unlit)
// partition each plane's cross-section of the view frustum into pieces of
// each region; the plane pass draws the fully lit and uncertain pieces with
// different programs and never the unlit ones.
//
// A plane stands for its slab [k·dz, (k+1)·dz] of view depth and samples it at
// its middle (plane_pass.hpp), so the cross-section is taken there: a full
// slab's sample then lies on the polygon that classified it. Where what a
// fragment takes may lie up to `margin` from that middle (lit sampling's
// pieces, Γ over the slab), the outer boxes grow and the inner ones shrink by
// it: a path to the light from within `margin` of a point runs within `margin`
// of that point's path (the two meet at a point light, run parallel toward a
// directional one), so a point fully lit among the grown boxes has its whole
// neighbourhood fully lit, and likewise unlit among the shrunk ones.
#include "geometry/bounding_volumes.hpp"
#include "geometry/camera.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <utility>
#include <vector>

namespace airlight::kit {

// One corner of a piece's triangle: world position at its slab's middle, and the slab.
struct PieceVertex {
  glm::vec3 position;
  int plane;
};

class SlabPieces {
public:
  // The shadow casters' bounding volumes (geometry::bounding_volumes), in the scene's coordinates.
  void prepare(const Scene& scene);

  // Light `light`'s trees for this frame (the casters moved by the inputs' transforms, the
  // boxes grown or shrunk by margin), then planes 0 … count − 1 of spacing dz, clipped to
  // the half-spaces dot(xyz, x) + w >= 0 (the light's influence, widened as the planes'
  // clip distances are), partitioned into triangles.
  struct Pieces {
    std::vector<PieceVertex> fully_lit, uncertain;
  };
  Pieces build(const FrameInputs& inputs, int light, int count, float dz, float margin,
               const std::vector<glm::vec4>& clip);

  // Summed over the lights since reset(): piece polygons per region, the trees' nodes, build seconds.
  void reset();
  std::vector<std::pair<std::string, double>> stats() const;

private:
  std::vector<geometry::BoundingVolumes> volumes_;
  std::vector<int> meshes_;  // index into Scene::meshes per volume
  double polygons_[3] = {0.0, 0.0, 0.0};
  double nodes_ = 0.0, seconds_ = 0.0;
};

}  // namespace airlight::kit
