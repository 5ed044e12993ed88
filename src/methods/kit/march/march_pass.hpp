#pragma once
// The march pass of raymarch, interleaved (march.comp.glsl) and sv_march (its
// own program over march_pass.glsl): its settings, its program and noise
// texture, and its dispatches.
#include "methods/kit/sampling/noise.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <airlight/settings.hpp>
#include <functional>
#include <string>
#include <vector>

namespace airlight::kit {

// steps, jitter and sampling: the march's settings, common to its methods.
std::vector<SettingSpec> march_settings();

// The `sampling` setting: where the steps go (march.glsl's SAMPLING_*).
enum class Sampling { uniform, equiangular };

struct MarchSettings {
  int steps = 64;                        // N
  Jitter jitter = Jitter::none;
  Sampling sampling = Sampling::equiangular;
  int block = 1;                      // M: pixel q marches the samples k ≡ q (mod M²)
  bool normalized = false;            // divide each pixel's sum by its light guide (march.glsl)
  bool guard = false;                 // interleaved's guard: each pixel's spread, lamps' pixels kept (march.comp.glsl)

  // From the method's settings (those of march_settings()), with block M.
  static MarchSettings from(const Settings& settings, int block = 1, bool normalized = false, bool guard = false);
};

// The program, by default march.comp.glsl, may be a method's own march
// (sv_march): it includes march_pass.glsl, writes image unit 0 and gets the
// pass's defines after the frame's and `defines`.
class MarchPass {
public:
  explicit MarchPass(MarchSettings settings, std::string program = "methods/kit/march/march.comp.glsl",
                     std::string defines = "")
      : settings_(std::move(settings)), program_(std::move(program)), extra_defines_(std::move(defines)) {}

  // Uploads the noise tile; needs a current context. The program is compiled
  // at the first run (gpu::cached_compute_program).
  void prepare();

  // Writes each pixel's sum over its own samples into `target` (RGBA32F of the
  // frame's size; w = 1, or when normalized whether a light reaches the ray);
  // the frame must be bound (SceneFrame::bind), and what a method's own
  // program reads besides.
  // It runs in the context where link_ahead's warm-up ran
  // (SceneFrame::run_where_warmed): `bind_own`, run there first, binds what a
  // method's own program reads besides.
  void run(const kit::SceneFrame& frame, const gpu::Texture& target, const std::function<void()>& bind_own = {});
  // Starts linking run()'s program for this frame's defines and warming it
  // with `target` (GpuMethod::link_ahead); `bind_own` binds by values it
  // holds, as SceneFrame::warm_pixels says.
  void link_ahead(const kit::SceneFrame& frame, const gpu::Texture& target, std::function<void()> bind_own = {});

  // With `normalized`: each pixel's light guide (rgb) and volume key (w,
  // march.glsl) from the last run (RGBA32F).
  const gpu::Texture& guide() const { return guide_; }

  // With `guard`: per pixel Σ of squared successive differences (rgb) and its
  // own sample count (w) from the last run (RGBA32F).
  const gpu::Texture& spread() const { return spread_; }

  // Light samples evaluated by the last run (pixels × samples per pixel × lights).
  double light_samples() const { return light_samples_; }

private:
  struct Images {  // run()'s textures by their names, for the worker's thread
    GLuint target, noise, guide, spread;  // guide, spread: 0 unless normalized, guarded
    void bind() const;
  };
  Images images(const gpu::Texture& target) const;
  void size_for(const kit::SceneFrame& frame);
  std::string defines(const kit::SceneFrame& frame) const;

  MarchSettings settings_;
  std::string program_, extra_defines_;
  gpu::Texture noise_;
  gpu::Texture guide_;
  gpu::Texture spread_;
  int width_ = 0, height_ = 0;
  double light_samples_ = 0.0;
};

}  // namespace airlight::kit
