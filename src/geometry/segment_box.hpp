#pragma once
// Whether a segment meets an axis-aligned box: the conforming set's k-d tree
// walk and the random scenes' occlusion tests ask it.
#include <glm/vec3.hpp>

#include <algorithm>
#include <utility>

namespace airlight::geometry {

// Whether the segment p + t·d, t in [0, 1], meets the box [lo, hi] (slabs; a
// segment along a face counts as meeting it).
inline bool segment_meets_box(const glm::dvec3& p, const glm::dvec3& d, const glm::dvec3& lo, const glm::dvec3& hi) {
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0.0) {
      if (p[axis] < lo[axis] || p[axis] > hi[axis]) return false;
      continue;
    }
    double t0 = (lo[axis] - p[axis]) / d[axis], t1 = (hi[axis] - p[axis]) / d[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0), leave = std::min(leave, t1);
    if (enter > leave) return false;
  }
  return true;
}

}  // namespace airlight::geometry
