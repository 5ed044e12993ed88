#include "view/display.hpp"

#include "gpu/program.hpp"

namespace airlight::view {

namespace {

constexpr int display_values = 3;  // display.frag.glsl's `pass` beyond the three of Pass

int texture_width(GLuint texture) {
  GLint width = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &width);
  return width;
}

}  // namespace

Display::Display()
    : empty_(gpu::make_vertex_array()), nearest_(gpu::make_sampler(GL_NEAREST)),
      bilinear_(gpu::make_sampler(GL_LINEAR)) {}

void Display::draw(GLuint airlight, GLuint surface, int x, int y, int width, int height, Pass pass,
                   const ToneMap& tone) const {
  run(airlight, surface, x, y, width, height, static_cast<int>(pass), tone);
}

void Display::draw_display_values(GLuint image, int x, int y, int width, int height) const {
  run(image, image, x, y, width, height, display_values, {});
}

// `mode`: a Pass, or display_values.
void Display::run(GLuint airlight, GLuint surface, int x, int y, int width, int height, int mode,
                  const ToneMap& tone) const {
  const gpu::Program& program = gpu::cached_program(
      {{GL_VERTEX_SHADER, "view/display.vert.glsl"}, {GL_FRAGMENT_SHADER, "view/display.frag.glsl"}});
  glUseProgram(program.id());
  gpu::set_uniform(program, "pass", mode);
  gpu::set_uniform(program, "exposure", tone.exposure);
  gpu::set_uniform(program, "curve", static_cast<int>(tone.curve));
  gpu::set_uniform(program, "viewport", glm::vec4(x, y, width, height));
  glBindTextureUnit(0, airlight);
  glBindTextureUnit(1, surface);
  // Full size: each pixel as it is. Reduced: stretched bilinearly (a NaN pixel
  // then darkens its neighbours too; the full-size frame shows it alone).
  const GLuint sampler = texture_width(airlight) == width ? nearest_.id() : bilinear_.id();
  glBindSampler(0, sampler);
  glBindSampler(1, sampler);
  glViewport(x, y, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(empty_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(0, 0);  // methods bind their own textures to these units, with no sampler object
  glBindSampler(1, 0);
}

}  // namespace airlight::view
