#include "methods/kit/frame/scene_frame.hpp"

#include "methods/kit/frame/scene_frame_parts.hpp"

#include <algorithm>
#include <cfloat>

namespace airlight::kit {

using namespace gpu;

// Unused kinds get a 1×1 texture so that every sampler stays bound and valid.
void SceneFrame::allocate_shadow_maps(const ShadowLayout& layout, int resolution) {
  shadow_layout_ = layout;
  shadow_resolution_ = resolution;
  const int maps = layout.maps, cubes = layout.cubes;
  const int map_size = maps ? resolution : 1, cube_size = cubes ? resolution : 1;
  shadow_maps_ = make_texture(GL_TEXTURE_2D_ARRAY, GL_R32F, map_size, map_size, std::max(maps, 1));
  shadow_cubes_ = make_texture(GL_TEXTURE_CUBE_MAP_ARRAY, GL_R32F, cube_size, cube_size, 6 * std::max(cubes, 1));
  shadow_depth_ = render_target(GL_DEPTH_COMPONENT32F, resolution, resolution);
  glNamedFramebufferTexture(shadow_fbo_.id(), GL_DEPTH_ATTACHMENT, shadow_depth_.id(), 0);
}

void SceneFrame::draw_shadow_maps() {
  glBindTextureUnit(binding::shadow_maps, 0);
  glBindTextureUnit(binding::shadow_cubes, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_.id());
  glViewport(0, 0, shadow_resolution_, shadow_resolution_);
  glBindVertexArray(vertex_array_.id());
  for (const ShadowDraw& d : shadow_draws_) {
    const GLuint texture = d.cube ? shadow_cubes_.id() : shadow_maps_.id();
    glNamedFramebufferTextureLayer(shadow_fbo_.id(), GL_COLOR_ATTACHMENT0, texture, 0, d.layer);
    check_complete(shadow_fbo_, "shadow map");
    if (d.engine)
      import_shadow_layer(d);
    else
      draw_shadow_layer(d);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bind();
}

// One 2D map or cube face: cleared to FLT_MAX (no occluder: lit), then the scene.
void SceneFrame::draw_shadow_layer(const ShadowDraw& d) {
  const float far[4] = {FLT_MAX, 0.0f, 0.0f, 0.0f}, one = 1.0f;
  glClearNamedFramebufferfv(shadow_fbo_.id(), GL_COLOR, 0, far);
  glClearNamedFramebufferfv(shadow_fbo_.id(), GL_DEPTH, 0, &one);
  const Program& program = frame_program("methods/kit/frame/shadows/shadow.vert.glsl", "methods/kit/frame/shadows/shadow.frag.glsl", defines_);
  glUseProgram(program.id());
  set_uniform(program, "light_view_projection", d.matrix);
  set_uniform(program, "light_index", d.light);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDrawElements(GL_TRIANGLES, caster_index_count_, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_DEPTH_TEST);
}

}  // namespace airlight::kit
