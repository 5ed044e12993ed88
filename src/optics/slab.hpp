#pragma once
// Line against an axis-aligned box by slabs (Kay & Kajiya 1986): the bounded
// volumes of media.cpp in world axes, a directional light's beam in its own
// frame (light.cpp). shaders/optics/media.glsl box_overlap is the GLSL twin.
#include <algorithm>
#include <glm/vec3.hpp>

namespace airlight::optics {

// A parameter interval [lo, hi] along a line; empty unless lo < hi.
struct Interval {
  double lo = 0.0, hi = 0.0;
  bool empty() const { return !(lo < hi); }
};

// The part of [t0, t1] where o + t·d lies inside the closed box [lo, hi]. A
// zero component of d is decided by o alone (inside or outside that slab for
// every t), so no 0/0 NaN enters the min/max; a tiny non-zero one gives huge
// or infinite bounds, which min/max handle. t0, t1 may be infinite.
inline Interval slab_overlap(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& lo,
                             const glm::dvec3& hi, double t0, double t1) {
  Interval in{t0, t1};
  for (int axis = 0; axis < 3; ++axis) {
    if (d[axis] == 0.0) {
      if (o[axis] < lo[axis] || o[axis] > hi[axis]) return {};
      continue;
    }
    double ta = (lo[axis] - o[axis]) / d[axis], tb = (hi[axis] - o[axis]) / d[axis];
    if (ta > tb) std::swap(ta, tb);
    in.lo = std::max(in.lo, ta);
    in.hi = std::min(in.hi, tb);
  }
  return in;
}

}  // namespace airlight::optics
