#include "methods/interleaved/gather_pass.hpp"

#include "gpu/program.hpp"

#include <string>

namespace airlight::methods {
namespace {

constexpr GLuint partial_unit = kit::binding::first_free_texture;

}  // namespace

void GatherPass::run(const kit::SceneFrame& frame, const gpu::Texture& image) {
  if (frame.width() != width_ || frame.height() != height_) {
    width_ = frame.width();
    height_ = frame.height();
    rows_ = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width_, height_);
  }
  const gpu::Program& program = gpu::cached_compute_program(
      "methods/interleaved/gather.comp.glsl",
      frame.defines() + "#define BINDING_PARTIAL " + std::to_string(partial_unit) + "\n");
  glUseProgram(program.id());
  gpu::set_uniform(program, "block", settings_.block);
  gpu::set_uniform(program, "depth_aware", settings_.depth_aware ? 1 : 0);
  gpu::set_uniform(program, "depth_threshold", settings_.depth_threshold);
  gpu::set_uniform(program, "normalized", settings_.normalized ? 1 : 0);
  pass(program, frame, image, rows_, false);
  pass(program, frame, rows_, image, true);
}

void GatherPass::pass(const gpu::Program& program, const kit::SceneFrame& frame, const gpu::Texture& from,
                      const gpu::Texture& to, bool vertical) {
  gpu::set_uniform(program, "vertical", vertical ? 1 : 0);
  glBindTextureUnit(partial_unit, from.id());
  glBindImageTexture(0, to.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gpu::dispatch_pixels(frame.width(), frame.height());
}

}  // namespace airlight::methods
