#pragma once
// The base of every GPU method (DESIGN §3): prepare() creates the headless GL
// context (its Failure names what to install: the command exits 1) and uploads
// the scene into the shared frame; render() runs the frame's passes (G-buffer,
// shadow maps, surface), then the method's airlight passes into an RGBA32F
// target, and reads back L_air and L_surf·T(d) with every pass's GPU time.
#include "gpu/context.hpp"
#include "methods/kit/scene_frame.hpp"
#include "gpu/timer.hpp"

#include <airlight/method.hpp>
#include <string>
#include <utility>
#include <vector>

namespace airlight::kit {

// The settings every GPU method shares (shadow_resolution, shadow_bias), to put
// in front of the method's own: gpu_settings({...own specs...}).
std::vector<SettingSpec> gpu_settings(std::vector<SettingSpec> own = {});

class GpuMethod : public Method {
public:
  explicit GpuMethod(const Settings& settings);
  void prepare(const Scene& scene) final;
  airlight::Frame render(int width, int height) final;

protected:
  // After the frame is prepared, with the context current: programs, tables.
  virtual void prepare_airlight(const Scene& scene) = 0;
  // Writes L_air into `target` (RGBA32F, frame.width() × frame.height()), timing
  // its passes with `timer` (e.g. ScopedPass(timer, "airlight")). The frame's
  // buffers and textures are bound (SceneFrame::bind) when it is called.
  virtual void render_airlight(const SceneFrame& frame, const Texture& target, PassTimer& timer) = 0;
  // Method-specific counters for Frame::stats.
  virtual std::vector<std::pair<std::string, double>> stats() const { return {}; }

private:
  FrameSettings frame_settings_;
  Context* context_ = nullptr;
  SceneFrame frame_;
  Texture airlight_;
  int width_ = 0, height_ = 0;
};

}  // namespace airlight::kit
