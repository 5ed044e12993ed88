#pragma once
// The depth range airlight supports (docs/design.md §4), checked alike by the
// scene file, a glTF camera and every frame's inputs.
#include "core/number_text.hpp"

#include <airlight/scene.hpp>
#include <string>

namespace airlight::scene_camera {

// Why `camera`'s far/near is beyond what airlight supports, or empty when it is
// not: a depth buffer resolves distance at the far plane to about
// far/near · 2⁻²⁴ of it, 0.6 % at the limit.
inline std::string depth_range_problem(const Camera& camera) {
  const double ratio = double(camera.far) / double(camera.near);
  if (ratio <= max_far_over_near) return {};
  return "far/near = " + number_text(ratio) + " is above the " + number_text(max_far_over_near) +
         " airlight supports (depth precision)";
}

}  // namespace airlight::scene_camera
