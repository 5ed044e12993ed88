#include "methods/beam_volumes/signed_faces.hpp"

#include "gpu/program.hpp"
#include "methods/kit/counting/counted_draw.hpp"

namespace airlight::methods {

void SignedFaces::prepare() {
  fbo_ = gpu::make_framebuffer();
  no_vertices_ = gpu::make_vertex_array();
}

// No depth test or culling, no near or far clipping; GL_ONE, GL_ONE blending.
void SignedFaces::run(const kit::SceneFrame& frame, const kit::CrossingGeometry& geometry, const gpu::Texture& target,
                      gpu::PassTimer& timer) {
  gpu::ScopedPass pass(timer, "airlight");
  const kit::CountedTriangles faces = geometry.triangles();
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glClearTexImage(target.id(), 0, GL_RGBA, GL_FLOAT, zero);
  if (faces.size() == 0) return;
  if (!faces.on_gpu) faces_.assign(faces.on_cpu);
  const gpu::Buffer& buffer = faces.on_gpu ? *faces.on_gpu : faces_.buffer();
  const gpu::Program& program = gpu::cached_program(
      {{GL_VERTEX_SHADER, "methods/kit/counting/crossings.vert.glsl"}, {GL_FRAGMENT_SHADER, "methods/beam_volumes/signed.frag.glsl"}},
      frame.defines() + kit::lit_interval_defines());
  glUseProgram(program.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kit::binding::first_free_storage, buffer.id());
  glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, frame.width(), frame.height());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glEnable(GL_DEPTH_CLAMP);
  glBindVertexArray(no_vertices_.id());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * faces.size()));
  glDisable(GL_DEPTH_CLAMP);
  glDisable(GL_BLEND);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace airlight::methods
