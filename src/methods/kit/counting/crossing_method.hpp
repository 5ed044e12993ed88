#pragma once
// A method that counts crossings (docs/design.md §3): every frame its geometry
// built (CrossingGeometry) and turned into L_air by a CrossingPass, the lit
// intervals' by default. Its stats are the geometry's, then the pass's.
#include "methods/kit/counting/crossing_geometry.hpp"
#include "methods/kit/counting/lit_interval_pass.hpp"
#include "methods/kit/method/gpu_method.hpp"

#include <memory>

namespace airlight::kit {

class CrossingMethod final : public GpuMethod {
public:
  CrossingMethod(const Settings& settings, std::unique_ptr<CrossingGeometry> geometry,
                 std::unique_ptr<CrossingPass> pass);
  // With the lit-interval pass at the settings.
  CrossingMethod(const Settings& settings, std::unique_ptr<CrossingGeometry> geometry);

private:
  void prepare_airlight(const Scene& scene) override;
  void link_ahead(const SceneFrame& frame, const Texture& target) override {
    // The pass's programs first: the geometry's build, which runs first, takes
    // back what the worker has not begun (LightVolumeMesh::link_ahead); the
    // resolve's link and warm-up would hold a build queued after it.
    pass_->link_ahead(frame, target);
    geometry_->link_ahead(frame);
  }
  void build_frame(const SceneFrame& frame, PassTimer& timer) override;
  void render_airlight(const SceneFrame& frame, const Texture& target, PassTimer& timer) override;
  bool uses_shadow_maps() const override { return geometry_->uses_shadow_maps(); }
  bool draws_on_grid() const override { return true; }
  std::vector<std::pair<std::string, double>> stats() const override;

  std::unique_ptr<CrossingGeometry> geometry_;
  std::unique_ptr<CrossingPass> pass_;
};

}  // namespace airlight::kit
