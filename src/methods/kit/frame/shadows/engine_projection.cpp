#include "methods/kit/frame/shadows/engine_projection.hpp"

#include <algorithm>
#include <cmath>

namespace airlight::kit {

// A shadow texel's world size at distance r is (per_distance·r + constant) /
// resolution: read off an engine's projection (perspective: 2/P₁₁ at unit
// distance; orthographic: 2/P₁₁ everywhere), the larger of the two axes.
Projection engine_projection(const EngineShadow& e) {
  const glm::mat4& p = e.projection;
  const float across = 2.0f / std::max(std::min(std::abs(p[0][0]), std::abs(p[1][1])), 1e-30f);
  const bool perspective = p[3][3] == 0.0f;
  return {p * e.view, perspective ? across : 0.0f, perspective ? 0.0f : across};
}

// The window depth a projection gives its far plane (1, or 0 under reversed-Z):
// where an engine cleared its depth buffer, no surface or occluder was drawn.
float far_window_depth(const glm::mat4& projection) {
  const glm::vec4 near = projection * glm::vec4(0, 0, -1, 1), further = projection * glm::vec4(0, 0, -2, 1);
  return further.z / further.w < near.z / near.w ? 0.0f : 1.0f;
}

}  // namespace airlight::kit
