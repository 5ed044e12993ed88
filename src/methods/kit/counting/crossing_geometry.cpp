#include "methods/kit/counting/crossing_geometry.hpp"

#include <chrono>

namespace airlight::kit {

void CasterCrossings::prepare(const Scene& scene) {
  std::vector<int> casters;
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (scene.meshes[m].casts_shadows) casters.push_back(static_cast<int>(m));
  prepare_casters(scene, casters);
}

void CasterCrossings::build(const FrameInputs& inputs) {
  const auto start = std::chrono::steady_clock::now();
  triangles_.clear();
  add_triangles(inputs);
  build_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace airlight::kit
