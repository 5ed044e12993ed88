#pragma once
// The base of every GPU method (docs/design.md §3). prepare() takes the GL
// context (the headless one, or the engine's after use_current_gl_context();
// a missing driver is a Failure naming what to install: the command exits 1)
// and uploads what the scene fixes into the shared frame. Each frame runs the
// frame's passes (G-buffer, shadow maps, surface) for this frame's inputs, then
// the method's airlight passes into an RGBA32F target that stays on the GPU;
// read_back() copies L_air and L_surf·T(d) to the CPU with every pass's time.
// In an engine's frame the results go to the engine's textures instead.
#include "gpu/timer.hpp"
#include "methods/kit/frame/scene_frame.hpp"
#include "methods/kit/resolution/reduced_resolution.hpp"

#include <airlight/engine.hpp>
#include <airlight/method.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace airlight::gpu {
class Context;
}

namespace airlight::kit {

// The settings every GPU method shares (shadow_resolution, shadow_bias), to put
// in front of the method's own: gpu_settings({...own specs...}).
std::vector<SettingSpec> gpu_settings(std::vector<SettingSpec> own = {});
// Those of a method that evaluates the airlight per pixel: gpu_settings with
// the reduced resolution's (resolution_settings) after its own.
std::vector<SettingSpec> per_pixel_settings(std::vector<SettingSpec> own = {});

// MethodInfo::memory of a GPU method: the scene's meshes, the shadow maps,
// which every frame with a surface term draws whatever the method, and the
// method's own buffers.
MemoryEstimate gpu_memory(MemoryEstimate own = {});

class GpuMethod : public Method {
public:
  explicit GpuMethod(const Settings& settings);
  void prepare(const Scene& scene) final;
  void render_frame(const FrameInputs& inputs) final;
  void render_frame(const FrameInputs& inputs, const EngineFrame& engine) final;
  FrameImages read_back() const final;
  FrameNumbers numbers() const final;

protected:
  // After the frame is prepared, with the context current: what depends only
  // on the scene (tables, lattice meshes, noise tiles).
  virtual void prepare_airlight(const Scene& scene) = 0;
  // Once per frame, before any pass, once frame.defines() is this frame's:
  // starts linking the programs the method's last passes will use
  // (gpu::link_ahead), so that a new scene structure's first frame links them
  // beside the frame's other passes — after the CPU work that decides which
  // they are, where there is some (the planes' plan: PlanePass::plan) — and
  // a last compute pass warmed there as well (gpu::Warm, SceneFrame::
  // warm_pixels), then run in the worker's context. `target` is the one
  // render_airlight will be given at full resolution, already of this size.
  virtual void link_ahead(const SceneFrame& frame, const Texture& target) {
    (void)frame;
    (void)target;
  }
  // Once per frame, before render_airlight: what depends on the frame but not
  // on the pixel grid (a shadow volume, a light volume mesh), which a frame at
  // reduced resolution renders on two grids.
  virtual void build_frame(const SceneFrame& frame, PassTimer& timer) {
    (void)frame;
    (void)timer;
  }
  // Writes L_air into `target` (RGBA32F, frame.width() × frame.height()), timing
  // its passes with `timer` (e.g. ScopedPass(timer, "airlight")). The frame's
  // buffers and textures are bound (SceneFrame::bind) when it is called;
  // frame.inputs() is this frame's camera, lights and medium.
  virtual void render_airlight(const SceneFrame& frame, const Texture& target, PassTimer& timer) = 0;
  // Whether the method reads the lights' shadow maps: without, the frame draws none.
  virtual bool uses_shadow_maps() const { return true; }
  // Method-specific counters for FrameImages::stats.
  virtual std::vector<std::pair<std::string, double>> stats() const { return {}; }
  // With reduced resolution (resolution_settings()): how far, in pixels
  // (Chebyshev), the method's result at a pixel reads other pixels' results
  // of the same frame — what a recomputed pixel needs recomputed around it.
  virtual int recompute_halo() const { return 0; }
  // Whether the method draws on its grid with fragments that skip a pixel
  // whose grid distance is below their t: the pixels a recomputation leaves
  // out are then marked with −1 for them (SceneFrame::use_grid), which costs
  // the upsampling a store a pixel.
  virtual bool draws_on_grid() const { return false; }

private:
  void draw(const FrameInputs& inputs, const EngineFrame* engine);
  void render_reduced(PassTimer& timer);
  std::vector<std::pair<std::string, double>> frame_stats(bool finished) const;

  FrameSettings frame_settings_;
  gpu::Context* context_ = nullptr;
  SceneFrame frame_;
  Texture airlight_;
  int width_ = 0, height_ = 0;
  ReducedResolution resolution_;
  std::vector<std::pair<std::string, double>> coarse_stats_;  // the method's, of its run on the coarse grid
  std::optional<PassTimer> timer_;  // made by prepare(), in its context
  bool rendered_ = false;
};

}  // namespace airlight::kit
