#include "methods/raymarch/raymarch_method.hpp"

#include "gpu/gpu_method.hpp"
#include "methods/raymarch/march_pass.hpp"

#include <memory>

namespace airlight::methods {
namespace {

// Every pixel marches all N samples: the march pass with blocks of 1 pixel.
class Raymarch final : public gpu::GpuMethod {
public:
  explicit Raymarch(const Settings& s) : GpuMethod(s), march_(MarchSettings::from(s)) {}

private:
  void prepare_airlight(const Scene&) override { march_.prepare(); }

  void render_airlight(const gpu::SharedFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    gpu::ScopedPass pass(timer, "airlight");
    march_.run(frame, target);
  }

  std::vector<std::pair<std::string, double>> stats() const override {
    return {{"light_samples", march_.light_samples()}};
  }

  MarchPass march_;
};

}  // namespace

MethodInfo raymarch_method() {
  return {"raymarch", "Tóth 2009, Kingston 4.1",
          "per-pixel ray marching over the G-buffer distance with shadow-map (2D) or cube-map (point) "
          "visibility, samples at the middle of each step or jittered by a noise texture, in even steps "
          "or equiangular about each point and spot light",
          gpu::gpu_settings(march_settings()),
          [](const Settings& s) { return std::make_unique<Raymarch>(s); }};
}

}  // namespace airlight::methods
