#include "methods/kit/method/gpu_method.hpp"
#include "methods/kit/march/march_pass.hpp"

#include "methods/kit/method/registry.hpp"

#include <memory>

namespace airlight::methods {
namespace {

// Every pixel marches all N samples: the march pass with blocks of 1 pixel.
class Raymarch final : public kit::GpuMethod {
public:
  explicit Raymarch(const Settings& s) : GpuMethod(s), march_(kit::MarchSettings::from(s)) {}

private:
  void prepare_airlight(const Scene&) override { march_.prepare(); }
  void link_ahead(const kit::SceneFrame& frame, const gpu::Texture& target) override {
    march_.link_ahead(frame, target);
  }

  void render_airlight(const kit::SceneFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    gpu::ScopedPass pass(timer, "airlight");
    march_.run(frame, target);
  }

  std::vector<std::pair<std::string, double>> stats() const override {
    return {{"light_samples", march_.light_samples()}};
  }

  kit::MarchPass march_;
};

MethodInfo raymarch_method() {
  return {"raymarch", "Tóth 2009, Kingston 4.1",
          "per-pixel ray marching over the G-buffer distance with shadow-map (2D) or cube-map (point) "
          "visibility, samples at the middle of each step or jittered by a noise texture, in even steps "
          "or equiangular about each point and spot light",
          kit::per_pixel_settings(kit::march_settings()),
          kit::create<Raymarch>(),
          160, kit::gpu_memory(), {},
          {kit::high_quality_trial({"steps=512", "shadow_resolution=2048"},
            "512 equiangular steps per light and 2048² maps: at 32×24 a pixel spans many texels, so what is "
            "left is the sampling along the ray"), kit::reduced_trial("raymarch")}, {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(1, raymarch_method);

}  // namespace airlight::methods
