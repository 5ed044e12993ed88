#include "methods/interleaved/gather_pass.hpp"

#include "gpu/program.hpp"

#include <string>

namespace airlight::methods {
namespace {

constexpr GLuint partial_unit = kit::binding::first_free_texture;
constexpr GLuint guide_unit = partial_unit + 1;
constexpr GLuint spread_unit = partial_unit + 2;

}  // namespace

void GatherPass::run(const kit::SceneFrame& frame, const gpu::Texture& image, const gpu::Texture& guide,
                     const gpu::Texture& spread) {
  if (frame.gbuffer_width() != width_ || frame.gbuffer_height() != height_) {
    width_ = frame.gbuffer_width();
    height_ = frame.gbuffer_height();
    rows_ = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width_, height_);
  }
  glBindTextureUnit(guide_unit, guide.id());
  glBindTextureUnit(spread_unit, spread.id());
  pass(frame, image, rows_, false);
  pass(frame, rows_, image, true);
}

// One direction's program: the settings as constants (gather.comp.glsl).
void GatherPass::pass(const kit::SceneFrame& frame, const gpu::Texture& from, const gpu::Texture& to, bool vertical) {
  std::string defines = frame.defines() + "#define BINDING_PARTIAL " + std::to_string(partial_unit) + "\n" +
                        "#define BINDING_GUIDE " + std::to_string(guide_unit) + "\n" + "#define BINDING_SPREAD " +
                        std::to_string(spread_unit) + "\n" + "#define BLOCK " + std::to_string(settings_.block) +
                        "\n";
  if (vertical) defines += "#define VERTICAL\n";
  if (settings_.depth_aware) defines += "#define DEPTH_AWARE\n";
  if (settings_.normalized) defines += "#define NORMALIZED\n";
  if (settings_.guard > 0.0f) defines += "#define GUARD " + std::to_string(settings_.guard) + "\n";
  const gpu::Program& program = gpu::cached_compute_program("methods/interleaved/gather.comp.glsl", defines);
  glUseProgram(program.id());
  gpu::set_uniform(program, "depth_threshold", settings_.depth_threshold);
  glBindTextureUnit(partial_unit, from.id());
  glBindImageTexture(0, to.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  frame.dispatch_pixels();
}

}  // namespace airlight::methods
