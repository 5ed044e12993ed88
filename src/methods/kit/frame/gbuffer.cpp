#include "methods/kit/frame/scene_frame.hpp"

#include "gpu/context.hpp"
#include "methods/kit/frame/scene_frame_parts.hpp"

namespace airlight::kit {

using namespace gpu;

void SceneFrame::resize(int width, int height) {
  if (distance_ && width == inputs_.width && height == inputs_.height) return;
  gpu::Context::current().check_frame_size(width, height);
  distance_ = render_target(GL_R32F, width, height);
  normal_ = render_target(GL_RGBA32F, width, height);
  geometric_normal_ = render_target(GL_RGBA32F, width, height);
  albedo_ = render_target(GL_RGBA32F, width, height);
  depth_ = render_target(GL_DEPTH_COMPONENT32F, width, height);
  surface_ = render_target(GL_RGBA32F, width, height);
  const GLuint fbo = gbuffer_fbo_.id();
  const GLuint colors[] = {distance_.id(), normal_.id(), geometric_normal_.id(), albedo_.id()};
  GLenum buffers[4];
  for (GLuint k = 0; k < 4; ++k) {
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0 + k, colors[k], 0);
    buffers[k] = GL_COLOR_ATTACHMENT0 + k;
  }
  glNamedFramebufferDrawBuffers(fbo, 4, buffers);
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  check_complete(gbuffer_fbo_, "G-buffer");
}

void SceneFrame::draw_gbuffer() {
  // The G-buffer textures are the pass's outputs: unbind them as inputs meanwhile.
  for (GLuint unit : {binding::distance, binding::normal, binding::geometric_normal, binding::albedo})
    glBindTextureUnit(unit, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_.id());
  glViewport(0, 0, inputs_.width, inputs_.height);
  const float one = 1.0f;
  glClearNamedFramebufferfv(gbuffer_fbo_.id(), GL_DEPTH, 0, &one);
  glBindVertexArray(vertex_array_.id());
  glDisable(GL_DEPTH_TEST);  // the far-plane background first, then the meshes over it
  glUseProgram(frame_program("methods/kit/frame/fullscreen.vert.glsl", "methods/kit/frame/background.frag.glsl", defines_).id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(frame_program("methods/kit/frame/gbuffer.vert.glsl", "methods/kit/frame/gbuffer.frag.glsl", defines_).id());
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bind();
}

}  // namespace airlight::kit
