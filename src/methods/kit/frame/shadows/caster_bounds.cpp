#include "methods/kit/frame/shadows/caster_bounds.hpp"

#include "methods/kit/frame/model_of.hpp"

namespace airlight::kit {

Bounds caster_bounds(const Mesh& mesh) {
  Bounds b;
  if (!mesh.casts_shadows) return b;
  for (const glm::vec3& p : mesh.positions) b.add(glm::dvec3(p));
  return b;
}

Bounds world_bounds(const std::vector<Bounds>& meshes, const std::vector<glm::mat4>& transforms) {
  Bounds b;
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Bounds& local = meshes[m];
    if (local.empty()) continue;
    const glm::dmat4 model = glm::dmat4(model_of(transforms, m));
    for (int k = 0; k < 8; ++k) b.add(glm::dvec3(model * glm::dvec4(local.corner(k), 1.0)));
  }
  return b;
}

}  // namespace airlight::kit
