#include "methods/kit/gpu_method.hpp"
#include "methods/planes/plane_pass.hpp"

#include "methods/kit/registry.hpp"

#include <memory>

namespace airlight::methods {
namespace {

class Planes final : public kit::GpuMethod {
public:
  explicit Planes(const Settings& s) : GpuMethod(s), pass_(PlaneSettings::from(s)) {}

private:
  void prepare_airlight(const Scene& scene) override { pass_.prepare(scene); }

  void render_airlight(const kit::SceneFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    gpu::ScopedPass pass(timer, "airlight");
    pass_.run(frame, target);
  }

  std::vector<std::pair<std::string, double>> stats() const override {
    return {{"planes", pass_.planes_drawn()},
            {"fragments", pass_.fragments()},
            {"rebuilt_lights", pass_.regions().rebuilt()},
            {"rebuild_s", pass_.regions().seconds()}};
  }

  PlanePass pass_;
};

MethodInfo planes_method() {
  return {"planes", "Dobashi 2000",
          "virtual planes parallel to the image plane, one set per light from the eye to the far end of its lit "
          "region, clipped to the light's influence volume, depth-tested against the scene; each fragment adds "
          "I(θ,φ)·ξ·V·Δt (light map, ξ per fragment or on a lattice mesh, shadow-map test) by additive blending "
          "into a float target",
          kit::gpu_settings(plane_settings()), [](const Settings& s) { return std::make_unique<Planes>(s); }};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(3, planes_method);

}  // namespace airlight::methods
