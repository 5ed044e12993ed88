#include "optics/media.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

#include "optics/light.hpp"
#include "optics/phase.hpp"
#include "optics/slab.hpp"

namespace airlight::optics {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();

// The part of [t0, t1] where origin + t·dir lies inside the box.
Interval box_overlap(const Volume& box, const glm::dvec3& origin, const glm::dvec3& dir, double t0,
                     double t1) {
  return slab_overlap(origin, dir, glm::dvec3(box.min), glm::dvec3(box.max), t0, t1);
}

bool contains(const Volume& box, const glm::dvec3& x) {
  for (int axis = 0; axis < 3; ++axis)
    if (x[axis] < box.min[axis] || x[axis] > box.max[axis]) return false;
  return true;
}

// Σ over bounded volumes of σt · (length of origin + t·dir, t in [t0, t1], inside).
glm::dvec3 volumes_depth(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& dir,
                         double t0, double t1) {
  glm::dvec3 depth(0.0);
  for (const Volume& v : scene.volumes) {
    const Interval in = box_overlap(v, origin, dir, t0, t1);
    if (!in.empty()) depth += glm::dvec3(v.sigma_t()) * (in.hi - in.lo);
  }
  return depth;
}

bool simplified(const Scene& scene) { return scene.light_model.type == LightModelType::simplified; }

}  // namespace

glm::dvec3 optical_depth(const Scene& scene, const glm::dvec3& a, const glm::dvec3& b) {
  const double length = glm::length(b - a);
  if (!(length > 0.0)) return glm::dvec3(0.0);
  const glm::dvec3 dir = (b - a) / length;
  return glm::dvec3(scene.medium.sigma_t()) * length + volumes_depth(scene, a, dir, 0.0, length);
}

glm::dvec3 eye_leg_depth(const Scene& scene, const glm::dvec3& a, const glm::dvec3& b) {
  return simplified(scene) ? glm::dvec3(0.0) : optical_depth(scene, a, b);
}

glm::dvec3 light_leg_depth(const Scene& scene, const Light& light, const glm::dvec3& x) {
  if (simplified(scene)) return glm::dvec3(0.0);  // Nilsson eq. 2.15: T = 1
  if (light.type != LightType::directional) return optical_depth(scene, x, glm::dvec3(light.position));
  const glm::dvec3 to_light = -glm::normalize(glm::dvec3(light.direction));
  // A beam is emitted at its aperture (docs/decisions.md): the leg is the
  // segment back to the aperture's plane, through the medium and the volumes.
  // s < 0 (upstream, where the beam sends nothing) counts as 0, keeping exp(-τ) <= 1.
  if (has_beam(light)) return optical_depth(scene, x, x + std::max(beam_depth(light, x), 0.0) * to_light);
  // docs/design.md §1: sunlight arrives unattenuated by the filling medium; bounded
  // volumes between x and infinity (toward the light) still absorb.
  return volumes_depth(scene, x, to_light, 0.0, infinity);
}

glm::dvec3 scattering(const Scene& scene, const glm::dvec3& x, double cos_theta) {
  if (simplified(scene))  // Nilsson eq. 2.14: isotropic, the medium only
    return glm::dvec3(scene.medium.sigma_s) / (4.0 * std::numbers::pi);
  glm::dvec3 sum = glm::dvec3(scene.medium.sigma_s) * phase(scene.medium.phase, cos_theta);
  for (const Volume& v : scene.volumes)
    if (contains(v, x)) sum += glm::dvec3(v.sigma_s) * phase(v.phase, cos_theta);
  return sum;
}

std::vector<double> volume_crossings(const Scene& scene, const glm::dvec3& origin,
                                     const glm::dvec3& dir, double t0, double t1) {
  std::vector<double> crossings;
  for (const Volume& v : scene.volumes) {
    const Interval in = box_overlap(v, origin, dir, -infinity, infinity);
    if (in.empty()) continue;
    for (double t : {in.lo, in.hi})
      if (t > t0 && t < t1) crossings.push_back(t);
  }
  std::sort(crossings.begin(), crossings.end());
  crossings.erase(std::unique(crossings.begin(), crossings.end()), crossings.end());
  return crossings;
}

}  // namespace airlight::optics
