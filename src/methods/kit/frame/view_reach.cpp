#include "methods/kit/frame/view_reach.hpp"

#include "geometry/camera.hpp"

#include <algorithm>
#include <glm/geometric.hpp>

namespace airlight::kit {

double view_reach(const FrameInputs& inputs) {
  const double aspect = double(inputs.width) / double(std::max(inputs.height, 1));
  return geometry::corner_distance(inputs.camera, aspect, inputs.camera.far);
}

double beyond_view(const FrameInputs& inputs, const glm::dvec3& light) {
  return 2.0 * (glm::length(light - glm::dvec3(inputs.camera.position)) + view_reach(inputs));
}

}  // namespace airlight::kit
