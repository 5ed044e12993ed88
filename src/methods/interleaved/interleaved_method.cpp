#include "methods/kit/method/gpu_method.hpp"
#include "methods/interleaved/gather_pass.hpp"
#include "methods/kit/march/march_pass.hpp"

#include "methods/kit/method/registry.hpp"

#include <memory>

namespace airlight::methods {
namespace {

// The march pass with blocks of M×M pixels (each pixel marches N/M² of the
// samples), then the gather passes over the same target.
class Interleaved final : public kit::GpuMethod {
public:
  explicit Interleaved(const Settings& s)
      : GpuMethod(s),
        block_(s.integer("block")),
        march_(kit::MarchSettings::from(s, s.integer("block"), normalized(s), guarded(s))),
        gather_({s.integer("block"), s.boolean("depth_aware"), static_cast<float>(s.real("depth_threshold")),
                 normalized(s), guarded(s) ? static_cast<float>(s.real("guard")) : 0.0f}) {}

private:
  enum class Gather { sum, normalized };  // the `gather` setting's choices, in order
  static bool normalized(const Settings& s) { return s.option<Gather>("gather") == Gather::normalized; }
  static bool guarded(const Settings& s) { return s.real("guard") > 0.0 && s.integer("block") > 1; }

  void prepare_airlight(const Scene&) override { march_.prepare(); }
  void link_ahead(const kit::SceneFrame& frame, const gpu::Texture& target) override {
    march_.link_ahead(frame, target);
  }

  void render_airlight(const kit::SceneFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    gather_.warm(frame, target, march_.guide(), march_.spread());  // here, before the march's wait for the worker
    {
      gpu::ScopedPass pass(timer, "march");
      march_.run(frame, target);
    }
    gpu::ScopedPass pass(timer, "gather");
    gather_.run(frame, target, march_.guide(), march_.spread());
  }

  std::vector<std::pair<std::string, double>> stats() const override {
    return {{"light_samples", march_.light_samples()}};
  }

  // The vertical gather at a pixel reads the horizontal one's within M − 1
  // rows, which reads partial sums within M − 1 columns (gather.comp.glsl).
  int recompute_halo() const override { return block_ - 1; }

  int block_;
  kit::MarchPass march_;
  GatherPass gather_;
};

MethodInfo interleaved_method() {
  using T = SettingSpec::Type;
  std::vector<SettingSpec> own = kit::march_settings();
  own.insert(own.end(),
             {{"block", T::integer, 4, 1, 8, {},
               "M: pixel (x, y) marches only the samples k ≡ (x mod M) + M·(y mod M) of the N (mod M²), so "
               "each pixel evaluates N/M² samples; the gather sums M×M pixels"},
              {"depth_aware", T::boolean, 1, 0, 1, {},
               "move each pixel's gather window to its own side of a silhouette (see depth_threshold), leave "
               "out neighbours still across and rescale the rest, so shafts do not bleed across silhouettes"},
              {"depth_threshold", T::real, 0.1, 0.0, 10.0, {},
               "relative G-buffer distance difference |d − d_pixel| / d_pixel beyond which a neighbour is "
               "left out of the depth-aware gather"},
              {"gather", T::choice, 1, 0, 0, {"sum", "normalized"},
               "sum = Tóth's sum of the window's partial sums; normalized = each partial sum divided by its "
               "pixel's unshadowed ∫σs·I/r² (exact per light, bounded volumes' σs included), the sum multiplied "
               "by the pixel's own, so that the 1/r² peak next to a light, the cone's edge and a volume's outline "
               "do not blur (with equiangular steps, N = 64, 13–24× less error than sum on teapot_spot, "
               "biri_sphere, three_lights); with bounded volumes, neighbours whose share of it that the lights "
               "reach differs by more than 0.1 are left out, as across a silhouette"},
              {"guard", T::real, 2.0, 0.0, 100.0, {},
               "k: each pixel's gathered value is clamped to its own N/M² samples' estimate ± k standard errors "
               "(successive differences), so that where the window's rays differ — a lamp's image, a shadow edge — "
               "the pixel keeps its own march and the error keeps falling as N grows; 0 = Tóth's gather"}});
  return {"interleaved", "Tóth 2009 §4.1",
          "raymarch with the N samples spread over M×M pixel blocks (interleaved sampling, Keller & "
          "Heidrich 2001) and gathered by a separable sum, normalized by each pixel's unshadowed ∫σs·I/r² and "
          "depth-aware by default",
          kit::per_pixel_settings(std::move(own)), kit::create<Interleaved>(),
          224, kit::gpu_memory(), {},
          {kit::high_quality_trial({"steps=512", "shadow_resolution=2048"},
            "512 equiangular samples per light over 4×4 blocks and 2048² maps: the gather blurs only within "
            "a block, guarded against silhouettes"), kit::reduced_trial("interleaved")}, {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(2, interleaved_method);

}  // namespace airlight::methods
