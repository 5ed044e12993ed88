#pragma once
// Lit intervals by counting crossings (lit_intervals.glsl): a method hands in,
// per frame, the triangles that bound each light's lit region with their
// weights, and each light's count at the eye; the pass draws their crossings
// with every pixel's view ray into per-pixel lists ("crossings") and sums Γ
// over each light's lit intervals into the target ("airlight",
// lit_intervals.comp.glsl). Shared by shadow_planes and beam_volumes.
#include "gpu/gl.hpp"
#include "gpu/growing_buffer.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <airlight/settings.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <utility>
#include <vector>

namespace airlight::kit {

// One triangle of a lit region's boundary (lit_intervals.glsl CountedTriangle).
struct CountedTriangle {
  glm::vec4 corners[3];  // homogeneous world positions; w = 0: at infinity
  glm::vec4 plane;       // unit normal n and n·x, computed in double (counted_plane)
  glm::ivec4 light_weight{0};  // light index, weight w
};

// The plane through three homogeneous points (at most one at infinity, which
// then gives the plane's direction), its normal normalized in double and
// oriented as (b − a) × (c − a): in float, a short edge far from the light
// loses the normal's direction, and a crossing's sign with it.
glm::vec4 counted_plane(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c);

// A counted plane through the eye (take_planes_at_eye): a ray crosses it at
// t = 0, by +weight where n·dir > 0.
struct EyePlane {
  glm::vec3 normal;
  int light = 0;
  int weight = 0;
};

// What the resolve starts each ray's counts from: per light, the count at a
// point just off the eye on the negative side of its planes through the eye,
// and those planes (at most max_eye_planes in all).
struct EyeCounts {
  std::vector<int> counts;
  std::vector<EyePlane> planes;
};
inline constexpr int max_eye_planes = 8;  // lit_intervals.comp.glsl's MAX_EYE_PLANES

// Light `light`'s (`source`'s) triangles among triangles[first, end) whose
// plane holds the light's rays, a shadow boundary, and passes through the eye as far as the GPU can tell (within 1e-5 of the coordinates'
// magnitude, float's rounding of the crossing test many times over) with the
// eye inside them: seen edge-on they cover no pixel, and a ray's crossing at
// t ≈ 0 is lost or taken on the side float rounding picks (random scene 31:
// the eye on a shadow plane, the shadow on the wrong side of a line through
// the image). Their weights become 0 and they are returned, with in `beside` a
// point off the eye on the negative side of all of them, where the caller
// counts; none when there are none, or more than `room`, or no such point is
// found (then they are left as they were). Triangles through the eye with the
// eye outside them are crossed by no ray from it: their weights become 0 too.
std::vector<EyePlane> take_planes_at_eye(std::vector<CountedTriangle>& triangles, size_t first, int light,
                                         const Light& source, const glm::dvec3& eye, size_t room, glm::dvec3& beside);

// samples: where Γ has no closed form, the points per lit interval that
// correct it (lit_gamma.glsl's SAMPLES).
SettingSpec gamma_samples_setting();

// capacity and samples: the settings of the pass (in front of a method's own).
std::vector<SettingSpec> lit_interval_settings();

// The crossing pool at width × height: its bytes beyond the default capacity,
// which the methods' bytes_per_pixel already holds, and its buffer.
std::vector<MemoryNeed> crossing_pool_needs(const Settings& settings, int width, int height);
// `count` counted triangles built on the CPU and uploaded: both copies.
MemoryNeed counted_triangle_need(const std::string& what, double count);

// "#define BINDING_COUNTED n" and the other bindings of lit_intervals.glsl: the
// counted triangles at binding::first_free_storage, the node pool after them.
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
  // crossings.vert.glsl, the records at BINDING_COUNTED); returns the fragment
  // shader invocations (0 without pipeline statistics).
  double draw(const SceneFrame& frame, const gpu::Program& program, const gpu::Buffer& triangles, size_t count);

private:
  void keep_crossing(const SceneFrame& frame, size_t n);

  size_t range_triangles_ = 1;  // triangles per storage binding
  gpu::GrowingBuffer<GLuint> kept_;  // the kept triangles' indices
  gpu::Buffer kept_draw_;            // their indirect draw
  gpu::Framebuffer fbo_;
  gpu::VertexArray no_vertices_;
  int width_ = 0, height_ = 0;
  gpu::Query invocations_;  // fragment shader invocations (GL_ARB_pipeline_statistics_query), when there
};

class LitIntervalPass {
public:
  explicit LitIntervalPass(const Settings& settings);

  // Needs a current context.
  void prepare();

  // The crossings of `triangles` with the frame's pixel rays, then Σ Γ over
  // each light's lit intervals into `target`; the frame must be bound.
  void run(const SceneFrame& frame, const std::vector<CountedTriangle>& triangles, const EyeCounts& eye,
           const gpu::Texture& target, gpu::PassTimer& timer);
  // The same with the triangles already on the GPU (a mesh a compute pass built).
  void run(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count, const EyeCounts& eye,
           const gpu::Texture& target, gpu::PassTimer& timer);

  // crossings (drawn into the lists), fragments (shaded by the last draw of
  // the triangles; 0 without pipeline statistics), redraws (the pool grown
  // this frame), loop_limited (pixels llvmpipe's loop limit cut short) and
  // passes (of the resolve: more than one where that limit was met).
  std::vector<std::pair<std::string, double>> stats() const;

private:
  void list_crossings(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count);
  void draw(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count);
  void resolve(const SceneFrame& frame, const EyeCounts& eye, const gpu::Texture& target);
  void resolve_in_passes(const SceneFrame& frame, const gpu::Program& program, const gpu::Texture& target);
  void allocate_pool(size_t nodes);
  std::string defines() const;

  double capacity_per_pixel_;
  int samples_;
  gpu::GrowingBuffer<CountedTriangle> triangles_;  // run()'s from the CPU
  gpu::Buffer nodes_, node_count_;
  size_t node_capacity_ = 0;
  gpu::Texture heads_;
  CountedDraw counted_draw_;
  int width_ = 0, height_ = 0;
  unsigned crossings_ = 0;
  double fragments_ = 0.0;
  int redraws_ = 0;
  GLuint loop_limited_ = 0;
  bool loop_limit_ = false;         // llvmpipe: the resolve runs in passes (LOOP_LIMIT)
  int passes_ = 1;                  // of the resolve (more on llvmpipe where its loop limit bites)
  gpu::Texture progress_;           // per pixel: intervals summed, or finished (LOOP_LIMIT), sized with heads_
};

}  // namespace airlight::kit
