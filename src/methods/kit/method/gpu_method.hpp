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
  // Writes L_air into `target` (RGBA32F, frame.width() × frame.height()), timing
  // its passes with `timer` (e.g. ScopedPass(timer, "airlight")). The frame's
  // buffers and textures are bound (SceneFrame::bind) when it is called;
  // frame.inputs() is this frame's camera, lights and medium.
  virtual void render_airlight(const SceneFrame& frame, const Texture& target, PassTimer& timer) = 0;
  // Whether the method reads the lights' shadow maps: without, the frame draws none.
  virtual bool uses_shadow_maps() const { return true; }
  // Method-specific counters for FrameImages::stats.
  virtual std::vector<std::pair<std::string, double>> stats() const { return {}; }

private:
  void draw(const FrameInputs& inputs, const EngineFrame* engine);

  FrameSettings frame_settings_;
  gpu::Context* context_ = nullptr;
  SceneFrame frame_;
  Texture airlight_;
  int width_ = 0, height_ = 0;
  std::optional<PassTimer> timer_;  // made by prepare(), in its context
  bool rendered_ = false;
};

}  // namespace airlight::kit
