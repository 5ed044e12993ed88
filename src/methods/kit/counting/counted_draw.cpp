#include "methods/kit/counting/counted_draw.hpp"

#include "gpu/program.hpp"

#include <algorithm>
#include <numeric>

namespace airlight::kit {

std::string lit_interval_defines() {
  return "#define BINDING_COUNTED " + std::to_string(counted_binding) + "\n#define BINDING_NODES " +
         std::to_string(nodes_binding) + "\n#define BINDING_NODE_COUNT " + std::to_string(node_count_binding) +
         "\n#define BINDING_KEPT " + std::to_string(kept_binding) + "\n#define BINDING_KEPT_DRAW " +
         std::to_string(kept_draw_binding) + "\n";
}

void CountedDraw::prepare() {
  fbo_ = gpu::make_framebuffer();
  no_vertices_ = gpu::make_vertex_array();  // the triangles come from their buffer by gl_VertexID
  kept_draw_ = gpu::make_buffer(4 * sizeof(GLuint), nullptr);
  kept_.release();
  // A storage binding holds at most GL_MAX_SHADER_STORAGE_BLOCK_SIZE bytes
  // (128 MiB on llvmpipe: 1.68 M triangles); larger sets are drawn in ranges
  // whose offsets keep the binding's alignment.
  GLint64 block = 0;
  GLint align = 16;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
  const size_t step = static_cast<size_t>(align) / std::gcd(static_cast<size_t>(align), sizeof(CountedTriangle));
  range_triangles_ = std::max<size_t>(static_cast<size_t>(block) / sizeof(CountedTriangle) / step * step, step);
  invocations_.prepare();
}

// The bound range's triangles that may cross a pixel's ray, into kept_ and the
// indirect draw's count (cull_counted.comp.glsl).
void CountedDraw::keep_crossing(const SceneFrame& frame, size_t n) {
  kept_.reserve(n);
  const GLuint command[4] = {0, 1, 0, 0};  // vertex count, instances, first vertex, base instance
  glNamedBufferSubData(kept_draw_.id(), 0, sizeof(command), command);
  const gpu::Program& cull =
      gpu::cached_compute_program("methods/kit/counting/cull_counted.comp.glsl", frame.defines() + lit_interval_defines());
  glUseProgram(cull.id());
  gpu::set_uniform(cull, "item_count", static_cast<int>(n));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kept_binding, kept_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kept_draw_binding, kept_draw_.id());
  const GLuint groups = static_cast<GLuint>((n + 63) / 64), x = std::min<GLuint>(groups, 65535u);
  glDispatchCompute(x, (groups + x - 1) / x, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, kept_draw_.id());
}

void CountedDraw::draw(const SceneFrame& frame, const gpu::Program& program, const gpu::Buffer& triangles,
                       size_t count) {
  if (frame.width() != width_ || frame.height() != height_) {
    width_ = frame.width();
    height_ = frame.height();
    glNamedFramebufferParameteri(fbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, width_);
    glNamedFramebufferParameteri(fbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, height_);
  }
  glUseProgram(program.id());
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_CLAMP);
  glBindVertexArray(no_vertices_.id());
  invocations_.begin();
  for (size_t first = 0; first < count; first += range_triangles_) {
    const size_t n = std::min(range_triangles_, count - first);
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, counted_binding, triangles.id(),
                      static_cast<GLintptr>(first * sizeof(CountedTriangle)),
                      static_cast<GLsizeiptr>(n * sizeof(CountedTriangle)));
    keep_crossing(frame, n);
    glUseProgram(program.id());
    glDrawArraysIndirect(GL_TRIANGLES, nullptr);
  }
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  invocations_.end();
  glDisable(GL_DEPTH_CLAMP);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

}  // namespace airlight::kit
