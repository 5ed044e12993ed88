#include "methods/interleaved/gather_pass.hpp"

#include "gpu/program.hpp"

#include <string>

namespace airlight::methods {
namespace {

constexpr GLuint partial_unit = kit::binding::first_free_texture;
constexpr GLuint guide_unit = partial_unit + 1;
constexpr GLuint spread_unit = partial_unit + 2;
constexpr const char* gather_program = "methods/interleaved/gather.comp.glsl";

}  // namespace

void GatherPass::run(const kit::SceneFrame& frame, const gpu::Texture& image, const gpu::Texture& guide,
                     const gpu::Texture& spread) {
  size_for(frame);
  glBindTextureUnit(guide_unit, guide.id());
  glBindTextureUnit(spread_unit, spread.id());
  pass(frame, image, rows_, false);
  pass(frame, rows_, image, true);
}

void GatherPass::warm(const kit::SceneFrame& frame, const gpu::Texture& image, const gpu::Texture& guide,
                      const gpu::Texture& spread) {
  if (warmed_ == frame.defines()) return;
  warmed_ = frame.defines();
  size_for(frame);
  for (const bool vertical : {false, true}) {
    const gpu::Program& program = gpu::cached_compute_program(gather_program, defines(frame, vertical));
    const gpu::Texture& from = vertical ? rows_ : image;
    const gpu::Texture& to = vertical ? image : rows_;
    frame.warm_pixels([&] {
      glBindTextureUnit(guide_unit, guide.id());
      glBindTextureUnit(spread_unit, spread.id());
      bind(program, from, to);
    })(program);
  }
  frame.bind();
}

void GatherPass::size_for(const kit::SceneFrame& frame) {
  if (frame.gbuffer_width() == width_ && frame.gbuffer_height() == height_) return;
  width_ = frame.gbuffer_width();
  height_ = frame.gbuffer_height();
  rows_ = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width_, height_);
}

// One direction's program: the settings as constants (gather.comp.glsl).
std::string GatherPass::defines(const kit::SceneFrame& frame, bool vertical) const {
  std::string d = frame.defines() + "#define BINDING_PARTIAL " + std::to_string(partial_unit) + "\n" +
                  "#define BINDING_GUIDE " + std::to_string(guide_unit) + "\n" + "#define BINDING_SPREAD " +
                  std::to_string(spread_unit) + "\n" + "#define BLOCK " + std::to_string(settings_.block) + "\n";
  if (vertical) d += "#define VERTICAL\n";
  if (settings_.depth_aware) d += "#define DEPTH_AWARE\n";
  if (settings_.normalized) d += "#define NORMALIZED\n";
  if (settings_.guard > 0.0f) d += "#define GUARD " + std::to_string(settings_.guard) + "\n";
  return d;
}

void GatherPass::bind(const gpu::Program& program, const gpu::Texture& from, const gpu::Texture& to) const {
  glUseProgram(program.id());
  gpu::set_uniform(program, "depth_threshold", settings_.depth_threshold);
  glBindTextureUnit(partial_unit, from.id());
  glBindImageTexture(0, to.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
}

void GatherPass::pass(const kit::SceneFrame& frame, const gpu::Texture& from, const gpu::Texture& to, bool vertical) {
  const gpu::Program& program = gpu::cached_compute_program(gather_program, defines(frame, vertical));
  bind(program, from, to);
  frame.dispatch_pixels();
}

}  // namespace airlight::methods
