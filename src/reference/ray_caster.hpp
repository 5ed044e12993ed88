#pragma once
// Exact ray queries against a scene's triangle meshes through Embree 3 (docs/design.md §3,
// reference): the first hit along a view ray and occlusion between two points.
// Robust traversal (RTC_SCENE_FLAG_ROBUST); one Embree geometry per mesh whose
// geometry id is the mesh's index in Scene::meshes. Queries are thread-safe.
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <optics/airlight.hpp>

namespace airlight::reference {

struct Hit {
  double t = 0.0;             // distance along the (unit) ray direction
  unsigned mesh = 0;          // index into Scene::meshes
  unsigned triangle = 0;      // index into Mesh::triangles
  double u = 0.0, v = 0.0;    // Embree barycentrics: p = (1-u-v)·p0 + u·p1 + v·p2
  glm::dvec3 geometric_normal{0.0};  // unit, as wound (not yet flipped toward anyone)
};

class RayCaster {
public:
  // Throws airlight::Failure with Embree's message when a device or scene cannot be
  // built, or when a mesh has an index out of range or a non-finite position.
  explicit RayCaster(const Scene& scene);
  ~RayCaster();
  RayCaster(RayCaster&&) noexcept;
  RayCaster& operator=(RayCaster&&) noexcept;

  // The nearest surface with t in [t_near, t_far], if any.
  std::optional<Hit> intersect(const optics::Ray& ray, double t_near, double t_far) const;
  // Is any shadow-casting surface (Mesh::casts_shadows) in [t_near, t_far]
  // along the unit direction `dir` from `origin`?
  bool occluded(const glm::dvec3& origin, const glm::dvec3& dir, double t_near, double t_far) const;

private:
  struct Embree;
  std::unique_ptr<Embree> embree_;
};

}  // namespace airlight::reference
