#include "gpu/state.hpp"

namespace airlight::gpu {
namespace {

// The capabilities SavedState records and restores.
std::array<GLenum, 8 + 8> capabilities() {
  std::array<GLenum, 8 + 8> caps{GL_DEPTH_TEST,          GL_BLEND,           GL_CULL_FACE,  GL_SCISSOR_TEST,
                                 GL_STENCIL_TEST,        GL_POLYGON_OFFSET_FILL, GL_DEPTH_CLAMP, GL_FRAMEBUFFER_SRGB};
  for (GLenum c = 0; c < 8; ++c) caps[8 + c] = GL_CLIP_DISTANCE0 + c;
  return caps;
}

void set_enabled(GLenum capability, bool on) { on ? glEnable(capability) : glDisable(capability); }

}  // namespace

SavedState::SavedState() {
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw_framebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_framebuffer_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertex_array_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active_texture_);
  glGetIntegerv(GL_VIEWPORT, viewport_.data());
  glGetIntegerv(GL_CLIP_ORIGIN, &clip_origin_);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clip_depth_);
  glGetIntegerv(GL_DEPTH_FUNC, &depth_func_);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask_);
  glGetBooleanv(GL_COLOR_WRITEMASK, color_mask_.data());
  glGetIntegerv(GL_BLEND_SRC_RGB, &blend_src_rgb_);
  glGetIntegerv(GL_BLEND_DST_RGB, &blend_dst_rgb_);
  glGetIntegerv(GL_BLEND_SRC_ALPHA, &blend_src_alpha_);
  glGetIntegerv(GL_BLEND_DST_ALPHA, &blend_dst_alpha_);
  glGetIntegerv(GL_BLEND_EQUATION_RGB, &blend_equation_rgb_);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &blend_equation_alpha_);
  const auto caps = capabilities();
  for (size_t k = 0; k < caps.size(); ++k) enabled_[k] = glIsEnabled(caps[k]);
  for (GLenum c : caps) glDisable(c);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthMask(GL_TRUE);
  glBlendEquation(GL_FUNC_ADD);
}

SavedState::~SavedState() {
  glUseProgram(static_cast<GLuint>(program_));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw_framebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer_));
  glBindVertexArray(static_cast<GLuint>(vertex_array_));
  glActiveTexture(static_cast<GLenum>(active_texture_));
  glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
  glClipControl(static_cast<GLenum>(clip_origin_), static_cast<GLenum>(clip_depth_));
  glDepthFunc(static_cast<GLenum>(depth_func_));
  glDepthMask(depth_mask_);
  glColorMask(color_mask_[0], color_mask_[1], color_mask_[2], color_mask_[3]);
  glBlendFuncSeparate(static_cast<GLenum>(blend_src_rgb_), static_cast<GLenum>(blend_dst_rgb_),
                      static_cast<GLenum>(blend_src_alpha_), static_cast<GLenum>(blend_dst_alpha_));
  glBlendEquationSeparate(static_cast<GLenum>(blend_equation_rgb_), static_cast<GLenum>(blend_equation_alpha_));
  const auto caps = capabilities();
  for (size_t k = 0; k < caps.size(); ++k) set_enabled(caps[k], enabled_[k]);
}

}  // namespace airlight::gpu
