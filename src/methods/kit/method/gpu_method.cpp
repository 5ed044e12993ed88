#include "methods/kit/method/gpu_method.hpp"

#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "gpu/state.hpp"
#include "methods/kit/engine/engine_output.hpp"
#include "methods/kit/method/memory_needs.hpp"

#include <airlight/error.hpp>
#include <chrono>
#include <cmath>

namespace airlight::kit {

std::vector<SettingSpec> gpu_settings(std::vector<SettingSpec> own) {
  using T = SettingSpec::Type;
  std::vector<SettingSpec> specs{
      {"shadow_resolution", T::integer, 1024, 64, 8192, {},
       "texels per side of each shadow map and cube face: shadow edges are resolved to one texel"},
      {"shadow_bias", T::real, 1.0, 0.0, 16.0, {},
       "shadow-map bias in texels at the point: surfaces move this far along their normal (1 clears "
       "self-shadowing at every incidence angle with nearest lookup); medium points take none"}};
  specs.insert(specs.end(), own.begin(), own.end());
  return specs;
}

std::vector<SettingSpec> per_pixel_settings(std::vector<SettingSpec> own) {
  for (SettingSpec& spec : resolution_settings()) own.push_back(std::move(spec));
  return gpu_settings(std::move(own));
}

namespace {

// ReducedResolution's textures: the coarse grid's airlight (16 bytes) and
// distance (4); with bilateral upsampling, on the full grid, at most: the
// recomputation's airlight (16), the failed pixels' list (4), and either
// their distance (4, for a method that draws on its grid) or, for a method
// that recomputes a halo, the halo's list (4) and distance (4) and a flag (4)
// a 2×2 block; two lists' headers of 16.
std::vector<MemoryNeed> resolution_needs(const Settings& settings, int width, int height) {
  const ResolutionSettings r = ResolutionSettings::from(settings);
  if (r.divisor == 1) return {};
  const double coarse = std::ceil(double(width) / r.divisor) * std::ceil(double(height) / r.divisor);
  const double full = double(width) * height, blocks = std::ceil(width / 2.0) * std::ceil(height / 2.0);
  return {{"scale", "the coarse grid's airlight and distance", 20.0 * coarse, 0.0, 16.0 * coarse},
          {"upsample", "at most: the recomputed pixels' distance, list and airlight on the full grid, and a halo's",
           r.bilateral ? 28.0 * full + 4.0 * blocks + 32.0 : 0.0, 0.0, r.bilateral ? 16.0 * full : 0.0}};
}

}  // namespace

MemoryEstimate gpu_memory(MemoryEstimate own) {
  return [own = std::move(own)](const Scene& scene, const Settings& settings, int width, int height) {
    std::vector<MemoryNeed> needs = shadow_map_needs(scene, settings);
    needs.push_back(geometry_need(scene));
    for (MemoryNeed& need : resolution_needs(settings, width, height)) needs.push_back(std::move(need));
    if (own)
      for (MemoryNeed& need : own(scene, settings, width, height)) needs.push_back(std::move(need));
    return needs;
  };
}

GpuMethod::GpuMethod(const Settings& settings)
    : frame_settings_{settings.integer("shadow_resolution"), static_cast<float>(settings.real("shadow_bias"))},
      resolution_(ResolutionSettings::from(settings)) {}

void GpuMethod::prepare(const Scene& scene) {
  context_ = &gpu::Context::current();
  gpu::SavedState state;
  frame_.prepare(scene);
  prepare_airlight(scene);
  timer_.emplace();  // in this context; frames count from 0
  rendered_ = false;
  context_->check("prepare");
}

void GpuMethod::render_frame(const FrameInputs& inputs) { draw(inputs, nullptr); }

void GpuMethod::render_frame(const FrameInputs& inputs, const EngineFrame& engine) { draw(inputs, &engine); }

void GpuMethod::draw(const FrameInputs& inputs, const EngineFrame* engine) {
  if (!context_) throw Failure("render_frame() before prepare()");
  if (engine) check_engine_frame(*engine, inputs);
  gpu::SavedState state;
  PassTimer& timer = *timer_;
  // Shadow maps for the method, or for the surface term (its lights are shadowed whatever the method).
  const bool surface = inputs.surface && (!engine || engine->target.surface);
  const SceneFrame::Needs needs{uses_shadow_maps() || surface, surface};
  frame_.set_inputs(inputs, frame_settings_, engine, needs);
  if (inputs.width != width_ || inputs.height != height_) {
    airlight_ = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, inputs.width, inputs.height);
    width_ = inputs.width;
    height_ = inputs.height;
  }
  link_ahead(frame_, airlight_);
  frame_.render_passes(engine, needs, timer);
  frame_.bind();
  build_frame(frame_, timer);
  if (resolution_.reduces())
    render_reduced(timer);
  else
    render_airlight(frame_, airlight_, timer);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  if (engine) write_engine_target(engine->target, frame_, airlight_, timer);
  timer.end_frame();  // its times are read when the GPU has written them: a frame never waits for its queries
  rendered_ = true;
  context_->check("render");
}

// The method on the coarse grid, upsampled; with bilateral upsampling, again
// on the full grid where the upsampling failed (ReducedResolution).
void GpuMethod::render_reduced(PassTimer& timer) {
  resolution_.reduce(frame_, timer);
  render_airlight(frame_, resolution_.coarse_target(), timer);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  coarse_stats_ = stats();
  if (!resolution_.upsample(frame_, airlight_, {recompute_halo(), draws_on_grid()}, timer)) return;
  render_airlight(frame_, resolution_.recompute_target(), timer);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  resolution_.merge(frame_, airlight_, timer);
}

// The method's counters — of its coarse run when the resolution is reduced,
// with the fraction of pixels recomputed when `finished` (reading it back
// waits for the frame: read_back's, not numbers()').
std::vector<std::pair<std::string, double>> GpuMethod::frame_stats(bool finished) const {
  if (!resolution_.reduces()) return stats();
  auto s = coarse_stats_;
  if (finished) s.emplace_back("recomputed_fraction", resolution_.recomputed_fraction());
  return s;
}

FrameNumbers GpuMethod::numbers() const {
  const gpu::FrameTimes times = timer_ ? timer_->ready() : gpu::FrameTimes{};
  return {times.frame, times.times, frame_stats(false)};
}

FrameImages GpuMethod::read_back() const {
  if (!rendered_) throw Failure("read_back() before render_frame()");
  gpu::SavedState state;
  const auto start = std::chrono::steady_clock::now();
  FrameImages images;
  images.airlight = gpu::read_image(airlight_, width_, height_);
  images.surface = gpu::read_image(frame_.surface(), width_, height_);
  images.readback_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  glFinish();  // the GPU has finished the frame (reading its images waited for it): its queries are in
  images.times = timer_->wait().times;
  images.stats = frame_stats(true);
  context_->check("read back");
  return images;
}

}  // namespace airlight::kit
