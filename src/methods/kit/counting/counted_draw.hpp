#pragma once
#include "gpu/gl.hpp"
#include "gpu/growing_buffer.hpp"
#include "gpu/query.hpp"
#include "methods/kit/counting/counted_triangles.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <string>

namespace airlight::kit {

// The storage bindings of lit_intervals.glsl: the counted triangles at
// binding::first_free_storage, the lit-interval pass's node pool after them,
// then CountedDraw's kept triangles.
inline constexpr GLuint counted_binding = binding::first_free_storage;
inline constexpr GLuint nodes_binding = counted_binding + 1;
inline constexpr GLuint node_count_binding = counted_binding + 2;
inline constexpr GLuint kept_binding = counted_binding + 3, kept_draw_binding = counted_binding + 4;

// "#define BINDING_COUNTED n" and the others above, for GLSL.
std::string lit_interval_defines();

// Counted triangles on the GPU rasterized with crossings.vert.glsl and a
// fragment stage of the caller's, over an attachment-less framebuffer of the
// frame's size: no depth test (a fragment compares its t with the G-buffer
// distance), no culling (both sides count), no near or far clipping
// (GL_DEPTH_CLAMP); in ranges no larger than one storage binding holds, each
// range's triangles first culled to those that may cross a pixel's ray
// (cull_counted.comp.glsl).
class CountedDraw {
public:
  void prepare();  // needs a current context

  // What a program of draw's needs on top of the frame's and lit_interval_defines.
  static std::string defines() { return "#define KEPT_TRIANGLES\n"; }

  // Draws records [0, count) of `triangles` with `program` (its vertex stage
  // crossings.vert.glsl, the records at BINDING_COUNTED).
  void draw(const SceneFrame& frame, const gpu::Program& program, const gpu::Buffer& triangles, size_t count);
  // The fragment shader invocations of the newest draw the GPU has finished,
  // read without waiting (0 before the first, or without pipeline statistics).
  double fragments() const { return invocations_.latest().value_or(0.0); }

private:
  void keep_crossing(const SceneFrame& frame, size_t n);

  size_t range_triangles_ = 1;  // triangles per storage binding
  gpu::GrowingBuffer<GLuint> kept_;  // the kept triangles' indices
  gpu::Buffer kept_draw_;            // their indirect draw
  gpu::Framebuffer fbo_;
  gpu::VertexArray no_vertices_;
  int width_ = 0, height_ = 0;
  gpu::InvocationCounter invocations_;
};

}  // namespace airlight::kit
