#include "methods/kit/gpu_method.hpp"

#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "gpu/state.hpp"
#include "methods/kit/memory_needs.hpp"

#include <airlight/error.hpp>
#include <chrono>
#include <tuple>

namespace airlight::kit {
namespace {

// The image format an engine's RGBA target is written with (engine.hpp).
struct ImageFormat {
  GLenum gl;
  const char* glsl;
};
ImageFormat image_format(GLuint texture, const char* what) {
  GLint format = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  if (format == GL_RGBA32F) return {GL_RGBA32F, "rgba32f"};
  if (format == GL_RGBA16F) return {GL_RGBA16F, "rgba16f"};
  throw InputError("EngineTarget", what, "must be an RGBA32F or RGBA16F texture");
}

void check_size(GLuint texture, const char* what, int width, int height) {
  GLint w = 0, h = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &w);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &h);
  if (w != width || h != height)
    throw InputError("EngineTarget", what,
                     "is " + std::to_string(w) + "x" + std::to_string(h) + ", the frame is " + std::to_string(width) +
                         "x" + std::to_string(height));
}

// An engine's frame against this frame's inputs, before anything is drawn.
void check_engine(const EngineFrame& engine, const FrameInputs& inputs) {
  const EngineTarget& t = engine.target;
  for (const auto& [texture, what] : {std::pair{t.airlight, "airlight"}, std::pair{t.transmittance, "transmittance"},
                                     std::pair{t.surface, "surface"}})
    if (texture) {
      check_size(texture, what, inputs.width, inputs.height);
      image_format(texture, what);
    }
  if (t.colour) check_size(t.colour, "colour", inputs.width, inputs.height);
  // The surface term is shaded from airlight's own G-buffer, which an engine's depth replaces.
  if (t.surface && (engine.depth || !inputs.surface))
    throw InputError("EngineTarget", "surface", "needs FrameInputs::surface and no EngineFrame::depth");
  if (engine.shadows.size() > inputs.lights.size())
    throw InputError("EngineFrame", "shadows", "has more entries than the frame has lights");
  for (size_t i = 0; i < engine.shadows.size(); ++i)
    if (engine.shadows[i] && engine.shadows[i]->kind == EngineShadow::Kind::cube &&
        inputs.lights[i].type == LightType::directional)
      throw InputError("EngineFrame", "shadows[" + std::to_string(i) + "]",
                       "is a cube map, but light " + std::to_string(i) + " is directional (it needs a 2D map)");
}

}  // namespace

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

MemoryEstimate gpu_memory(MemoryEstimate own) {
  return [own = std::move(own)](const Scene& scene, const Settings& settings, int width, int height) {
    std::vector<MemoryNeed> needs = shadow_map_needs(scene, settings);
    needs.push_back(geometry_need(scene));
    if (own)
      for (MemoryNeed& need : own(scene, settings, width, height)) needs.push_back(std::move(need));
    return needs;
  };
}

GpuMethod::GpuMethod(const Settings& settings)
    : frame_settings_{settings.integer("shadow_resolution"), static_cast<float>(settings.real("shadow_bias"))} {}

void GpuMethod::prepare(const Scene& scene) {
  context_ = &gpu::Context::current();
  gpu::SavedState state;
  frame_.prepare(scene);
  prepare_airlight(scene);
  rendered_ = false;
  context_->check("prepare");
}

void GpuMethod::render_frame(const FrameInputs& inputs) { draw(inputs, nullptr); }

void GpuMethod::render_frame(const FrameInputs& inputs, const EngineFrame& engine) { draw(inputs, &engine); }

void GpuMethod::draw(const FrameInputs& inputs, const EngineFrame* engine) {
  if (!context_) throw Failure("render_frame() before prepare()");
  if (engine) check_engine(*engine, inputs);
  gpu::SavedState state;
  PassTimer timer;
  // Shadow maps for the method, or for the surface term (its lights are shadowed whatever the method).
  const bool surface = inputs.surface && (!engine || engine->target.surface);
  frame_.render(inputs, frame_settings_, engine, {uses_shadow_maps() || surface, surface}, timer);
  if (inputs.width != width_ || inputs.height != height_) {
    airlight_ = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, inputs.width, inputs.height);
    width_ = inputs.width;
    height_ = inputs.height;
  }
  frame_.bind();
  render_airlight(frame_, airlight_, timer);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  if (engine) write_engine_target(engine->target, timer);
  times_ = timer.results();
  rendered_ = true;
  context_->check("render");
}

// L_air, T(d) and L_surf·T(d) into the engine's textures (engine_target.comp.glsl), then
// L = L_surf·T + L_air into its colour target by dual-source blending
// (engine_composite.frag.glsl): the engine's colour is only blended into.
void GpuMethod::write_engine_target(const EngineTarget& target, PassTimer& timer) {
  gpu::ScopedPass pass(timer, "engine");
  const std::string defines = frame_.defines();
  for (const auto& [texture, what, transmittance, source] :
       {std::tuple{target.airlight, "airlight", false, airlight_.id()},
        std::tuple{target.transmittance, "transmittance", true, airlight_.id()},
        std::tuple{target.surface, "surface", false, frame_.surface().id()}}) {
    if (!texture) continue;
    const ImageFormat format = image_format(texture, what);
    const Program& program = gpu::cached_compute_program(
        "methods/kit/engine_target.comp.glsl",
        defines + "#define TARGET_FORMAT " + format.glsl + "\n" + (transmittance ? "#define TRANSMITTANCE\n" : ""));
    glUseProgram(program.id());
    glBindImageTexture(0, source, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, texture, 0, GL_FALSE, 0, GL_WRITE_ONLY, format.gl);
    gpu::dispatch_pixels(width_, height_);
  }
  if (!target.colour) return;
  const gpu::Framebuffer fbo = gpu::make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, target.colour, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, width_, height_);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_SRC1_COLOR);  // L_air·1 + L_surf·T
  glUseProgram(gpu::cached_program({{GL_VERTEX_SHADER, "methods/kit/fullscreen.vert.glsl"},
                                    {GL_FRAGMENT_SHADER, "methods/kit/engine_composite.frag.glsl"}},
                                   defines)
                   .id());
  glBindTextureUnit(binding::first_free_texture, airlight_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
}

FrameNumbers GpuMethod::numbers() const { return {times_, stats()}; }

FrameImages GpuMethod::read_back() const {
  if (!rendered_) throw Failure("read_back() before render_frame()");
  gpu::SavedState state;
  const auto start = std::chrono::steady_clock::now();
  FrameImages images;
  images.airlight = gpu::read_image(airlight_, width_, height_);
  images.surface = gpu::read_image(frame_.surface(), width_, height_);
  images.times = times_;
  images.readback_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  images.stats = stats();
  context_->check("read back");
  return images;
}

}  // namespace airlight::kit
