#include "methods/kit/counting/crossing_method.hpp"

namespace airlight::kit {

CrossingMethod::CrossingMethod(const Settings& settings, std::unique_ptr<CrossingGeometry> geometry,
                               std::unique_ptr<CrossingPass> pass)
    : GpuMethod(settings), geometry_(std::move(geometry)), pass_(std::move(pass)) {}

CrossingMethod::CrossingMethod(const Settings& settings, std::unique_ptr<CrossingGeometry> geometry)
    : GpuMethod(settings),
      geometry_(std::move(geometry)),
      pass_(std::make_unique<LitIntervalPass>(settings, geometry_->has_eye_planes())) {}

void CrossingMethod::prepare_airlight(const Scene& scene) {
  geometry_->prepare(scene);
  pass_->prepare();
}

void CrossingMethod::build_frame(const SceneFrame& frame, PassTimer& timer) { geometry_->build(frame, timer); }

void CrossingMethod::render_airlight(const SceneFrame& frame, const Texture& target, PassTimer& timer) {
  pass_->run(frame, *geometry_, target, timer);
}

std::vector<std::pair<std::string, double>> CrossingMethod::stats() const {
  std::vector<std::pair<std::string, double>> s = geometry_->stats();
  for (auto& stat : pass_->stats()) s.push_back(std::move(stat));
  return s;
}

}  // namespace airlight::kit
