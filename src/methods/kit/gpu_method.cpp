#include "methods/kit/gpu_method.hpp"

#include <airlight/error.hpp>

namespace airlight::kit {

std::vector<SettingSpec> gpu_settings(std::vector<SettingSpec> own) {
  using T = SettingSpec::Type;
  std::vector<SettingSpec> specs{
      {"shadow_resolution", T::integer, 1024, 64, 8192, {},
       "texels per side of each shadow map and cube face: shadow edges are resolved to one texel"},
      {"shadow_bias", T::real, 1.0, 0.0, 16.0, {},
       "shadow-map bias in texels at the point: surfaces move this far along their normal (1 clears "
       "self-shadowing at every incidence angle with nearest lookup), medium points compare this much nearer"}};
  specs.insert(specs.end(), own.begin(), own.end());
  return specs;
}

GpuMethod::GpuMethod(const Settings& settings)
    : frame_settings_{settings.integer("shadow_resolution"), static_cast<float>(settings.real("shadow_bias"))} {}

void GpuMethod::prepare(const Scene& scene) {
  context_ = &Context::headless();
  frame_.prepare(scene);
  prepare_airlight(scene);
  context_->check("prepare");
}

airlight::Frame GpuMethod::render(int width, int height) {
  if (!context_) throw Failure("render() before prepare()");
  PassTimer timer;
  frame_.render(width, height, frame_settings_, timer);
  if (width != width_ || height != height_) {
    airlight_ = make_texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
    width_ = width;
    height_ = height;
  }
  frame_.bind();
  render_airlight(frame_, airlight_, timer);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  airlight::Frame frame;
  frame.airlight = read_image(airlight_, width, height);
  frame.surface = read_image(frame_.surface(), width, height);
  frame.times = timer.results();
  frame.stats = stats();
  context_->check("render");
  return frame;
}

}  // namespace airlight::kit
