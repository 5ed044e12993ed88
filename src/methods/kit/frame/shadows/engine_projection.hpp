#pragma once
// An engine's shadow maps and depth buffer as airlight reads them: the
// projection of its 2D map, and where its projections put their far plane.
#include "methods/kit/frame/shadows/shadow_projection.hpp"

#include <airlight/engine.hpp>
#include <glm/mat4x4.hpp>

namespace airlight::kit {

// An engine's 2D map: its matrix and texel size from its projection.
Projection engine_projection(const EngineShadow& engine);
// The window depth a projection gives its far plane (1, or 0 under reversed-Z).
float far_window_depth(const glm::mat4& projection);

}  // namespace airlight::kit
