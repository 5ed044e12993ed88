#pragma once
// What SceneFrame's files share (scene_frame.cpp, uploads.cpp, gbuffer.cpp,
// depth_import.cpp, shadows/shadow_maps.cpp, shadows/shadow_import.cpp):
// private to the frame.
#include "gpu/gl.hpp"
#include "gpu/program.hpp"
#include "optics/light.hpp"

#include <airlight/error.hpp>
#include <airlight/scene.hpp>
#include <string>

namespace airlight::kit {

// The lights whose gobo the GPU samples: spots and beams (a gobo means nothing elsewhere).
inline bool has_gobo(const Light& light) {
  return (light.type == LightType::spot || optics::has_beam(light)) && light.gobo && !light.gobo->empty();
}

// A render target of the frame (G-buffer, surface, shadow depth).
inline gpu::Texture render_target(GLenum format, int width, int height) {
  return gpu::make_texture(GL_TEXTURE_2D, format, width, height);
}

inline void check_complete(const gpu::Framebuffer& fbo, const char* what) {
  const GLenum status = glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Failure(std::string("the ") + what + " framebuffer is incomplete (status " + std::to_string(status) + ")");
}

inline const gpu::Program& frame_program(const char* vertex, const char* fragment, const std::string& defines) {
  return gpu::cached_program({{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, defines);
}

}  // namespace airlight::kit
