#include "methods/kit/engine/engine_output.hpp"

#include "gpu/program.hpp"

#include <airlight/error.hpp>
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

}  // namespace

void check_engine_frame(const EngineFrame& engine, const FrameInputs& inputs) {
  const EngineTarget& t = engine.target;
  for (const auto& [texture, what] : {std::pair{t.airlight, "airlight"}, std::pair{t.transmittance, "transmittance"},
                                     std::pair{t.surface, "surface"}})
    if (texture) {
      check_size(texture, what, inputs.width, inputs.height);
      image_format(texture, what);
    }
  if (t.color) check_size(t.color, "colour", inputs.width, inputs.height);
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

// Into the engine's textures (engine_target.comp.glsl), then
// L = L_surf·T + L_air into its colour target by dual-source blending
// (engine_composite.frag.glsl): the engine's colour is only blended into.
void write_engine_target(const EngineTarget& target, const SceneFrame& frame, const Texture& airlight, PassTimer& timer) {
  gpu::ScopedPass pass(timer, "engine");
  const std::string defines = frame.defines();
  for (const auto& [texture, what, transmittance, source] :
       {std::tuple{target.airlight, "airlight", false, airlight.id()},
        std::tuple{target.transmittance, "transmittance", true, airlight.id()},
        std::tuple{target.surface, "surface", false, frame.surface().id()}}) {
    if (!texture) continue;
    const ImageFormat format = image_format(texture, what);
    const Program& program = gpu::cached_compute_program(
        "methods/kit/engine/engine_target.comp.glsl",
        defines + "#define TARGET_FORMAT " + format.glsl + "\n" + (transmittance ? "#define TRANSMITTANCE\n" : ""));
    glUseProgram(program.id());
    glBindImageTexture(0, source, 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
    glBindImageTexture(1, texture, 0, GL_FALSE, 0, GL_WRITE_ONLY, format.gl);
    frame.dispatch_pixels();
  }
  if (!target.color) return;
  const gpu::Framebuffer fbo = gpu::make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, target.color, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, frame.width(), frame.height());
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_SRC1_COLOR);  // L_air·1 + L_surf·T
  glUseProgram(gpu::cached_program({{GL_VERTEX_SHADER, "methods/kit/frame/fullscreen.vert.glsl"},
                                    {GL_FRAGMENT_SHADER, "methods/kit/engine/engine_composite.frag.glsl"}},
                                   defines)
                   .id());
  glBindTextureUnit(binding::first_free_texture, airlight.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDisable(GL_BLEND);
}

}  // namespace airlight::kit
