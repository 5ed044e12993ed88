#include "methods/kit/frame/scene_frame.hpp"

#include "methods/kit/frame/scene_frame_parts.hpp"
#include "methods/kit/frame/shadows/engine_projection.hpp"

#include <glm/matrix.hpp>

namespace airlight::kit {

using namespace gpu;

// The engine's depth buffer as airlight's G-buffer: eye distances, and window
// depths of airlight's own projection for methods that depth-test (depth.frag.glsl).
void SceneFrame::import_depth(const EngineDepth& depth) {
  for (GLuint unit : {binding::distance, binding::normal, binding::geometric_normal, binding::albedo})
    glBindTextureUnit(unit, 0);
  const Program& program = frame_program("methods/kit/frame/fullscreen.vert.glsl", "methods/kit/frame/depth.frag.glsl", defines_);
  const glm::mat4 view_projection = depth.projection * depth.view;
  set_uniform(program, "engine_inverse_view_projection", glm::inverse(view_projection));
  set_uniform(program, "engine_zero_to_one", depth.range == DepthRange::zero_to_one ? 1 : 0);
  set_uniform(program, "engine_far_depth", far_window_depth(depth.projection));
  glBindTextureUnit(binding::engine_input, depth.texture);
  glBindSampler(binding::engine_input, nearest_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_.id());
  glViewport(0, 0, inputs_.width, inputs_.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);  // gl_FragDepth is written, not tested
  glBindVertexArray(vertex_array_.id());
  glUseProgram(program.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  glBindSampler(binding::engine_input, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bind();
}

}  // namespace airlight::kit
