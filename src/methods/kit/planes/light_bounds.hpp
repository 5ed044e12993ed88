#pragma once
// Where a light's virtual planes go (Dobashi §5.1; Nilsson 3.1 after Mitchell):
// the half-spaces bounding the light's influence volume, which clip each plane
// so that fragments outside it are never shaded, and the far end of the lit
// region, to which the planes extend.
#include "geometry/camera.hpp"
#include "reference/ray_caster.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <vector>

namespace airlight::kit {

struct LightBounds {
  // World half-spaces dot(xyz, x) + w >= 0 (unit xyz) whose intersection holds
  // every point the light reaches: 8 planes of a pyramid circumscribing a
  // spot's cone below 90°, the 6 faces of a beam; none for point lights,
  // unbounded directional lights and wider spots.
  std::vector<glm::vec4> clip;
  // False when light escapes to infinity (a ray from the light meets nothing):
  // the lit region then reaches the camera's far plane.
  bool bounded = false;
  // When bounded, points whose convex hull holds the lit region: the apex (or
  // the beam's aperture) and where the light's rays end on surfaces.
  std::vector<glm::dvec3> hull;
};

// Rays per side of the grid cast from a light to find where its light ends
// (per cube face for point lights and spots of 90° and wider).
inline constexpr int lit_region_rays = 128;

LightBounds light_bounds(const Light& light, const reference::RayCaster& rays);

// View depth (along the camera's forward axis) of the lit region's far end, in
// [0, far]: the deepest hull point, or `far` for an unbounded region. A grid of
// rays can miss a spike of geometry narrower than its spacing, which then ends
// the planes early there; 1% of the depth is added for it.
double lit_far_depth(const LightBounds& volume, const geometry::CameraBasis& camera, double far);

// Every light's bounds as the frames go by (docs/design.md §3: what a method
// rebuilds per frame). A light whose position, direction, cone, beam or
// gobo_up (which turns its grid of rays) changed is traced again — not one
// whose gobo image changed, which the rays do not see; when an object moves,
// the ray caster is rebuilt on the posed scene and every light is traced
// again. Nothing is redone for a frame that only moves the camera or changes
// colours and the medium.
class FrameLightBounds {
public:
  void prepare(const Scene& scene);
  void update(const FrameInputs& inputs);
  const std::vector<LightBounds>& bounds() const { return bounds_; }
  // Of the last update: lights traced again, and its seconds on the CPU.
  int rebuilt() const { return rebuilt_; }
  double seconds() const { return seconds_; }

private:
  Scene scene_;
  std::unique_ptr<reference::RayCaster> rays_;
  std::vector<glm::mat4> transforms_;
  std::vector<Light> lights_;
  std::vector<LightBounds> bounds_;
  int rebuilt_ = 0;
  double seconds_ = 0.0;
};

}  // namespace airlight::kit
