#pragma once
// A method that is the plane pass alone (plane_pass.hpp): planes (Dobashi 2000)
// and Nilsson's two hybrids differ only in how the planes are cut (PlaneCut).
#include "methods/kit/method/gpu_method.hpp"
#include "methods/kit/planes/plane_pass.hpp"

namespace airlight::kit {

class PlaneMethod final : public GpuMethod {
public:
  PlaneMethod(const Settings& s, PlaneCut cut) : GpuMethod(s), pass_(PlaneSettings::from(s, cut)) {}

private:
  void prepare_airlight(const Scene& scene) override { pass_.prepare(scene); }
  void link_ahead(const SceneFrame& frame, const Texture&) override { pass_.plan(frame); }

  void render_airlight(const SceneFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    gpu::ScopedPass pass(timer, "airlight");
    pass_.run(frame, target);
  }

  std::vector<std::pair<std::string, double>> stats() const override { return pass_.stats(); }

  PlanePass pass_;
};

}  // namespace airlight::kit
