#pragma once
// The caller's GL state around airlight's work in an engine's context
// (docs/design.md §3, "engine"): what a frame changes and puts back. Texture
// units, image units and buffer binding points are not restored (see
// <airlight/engine.hpp>); everything a caller's next draw depends on is.
#include "gpu/gl.hpp"

#include <array>

namespace airlight::gpu {

class SavedState {
public:
  // Records the state, then sets what airlight's passes assume: GL's default
  // clip control, no depth test, blending, culling or scissor.
  SavedState();
  ~SavedState();  // restores it
  SavedState(const SavedState&) = delete;
  SavedState& operator=(const SavedState&) = delete;

private:
  GLint program_ = 0, draw_framebuffer_ = 0, read_framebuffer_ = 0, vertex_array_ = 0, active_texture_ = 0;
  std::array<GLint, 4> viewport_{};
  GLint clip_origin_ = 0, clip_depth_ = 0, depth_func_ = 0;
  GLboolean depth_mask_ = GL_TRUE;
  std::array<GLboolean, 4> color_mask_{};
  GLint blend_src_rgb_ = 0, blend_dst_rgb_ = 0, blend_src_alpha_ = 0, blend_dst_alpha_ = 0;
  GLint blend_equation_rgb_ = 0, blend_equation_alpha_ = 0;
  std::array<GLboolean, 8 + 8> enabled_{};  // capabilities(), in order
};

}  // namespace airlight::gpu
