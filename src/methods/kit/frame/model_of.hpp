#pragma once
// Mesh `mesh`'s model matrix this frame: FrameInputs::transforms, or the
// identity for every mesh when the frame moves none (transforms empty).
#include <glm/mat4x4.hpp>

#include <cstddef>
#include <vector>

namespace airlight::kit {

inline glm::mat4 model_of(const std::vector<glm::mat4>& transforms, size_t mesh) {
  return transforms.empty() ? glm::mat4(1.0f) : transforms[mesh];
}

}  // namespace airlight::kit
