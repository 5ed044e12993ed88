#pragma once
// Lit intervals by counting crossings (lit_intervals.glsl): a geometry hands
// in, per frame, the triangles that bound each light's lit region with their
// weights, and each light's count at the eye (CrossingGeometry); the pass draws
// their crossings with every pixel's view ray into per-pixel lists
// ("crossings") and sums Γ over each light's lit intervals into the target
// ("airlight", lit_intervals.comp.glsl). The pass of shadow_planes,
// beam_volumes and light_volume (CrossingMethod); sv_march draws its shell
// with CountedDraw.
#include "gpu/gl.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/counting/crossing_geometry.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <airlight/settings.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <utility>
#include <vector>

namespace airlight::kit {

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
  gpu::Buffer kept_, kept_draw_;  // the kept triangles' indices; their indirect draw
  size_t kept_capacity_ = 0;
  gpu::Framebuffer fbo_;
  gpu::VertexArray no_vertices_;
  int width_ = 0, height_ = 0;
  gpu::Query invocations_;  // fragment shader invocations (GL_ARB_pipeline_statistics_query), when there
};

class LitIntervalPass final : public CrossingPass {
public:
  explicit LitIntervalPass(const Settings& settings);

  void prepare() override;

  // The crossings of the geometry's triangles (uploaded first if on the CPU)
  // with the frame's pixel rays, then Σ Γ over each light's lit intervals
  // from its eye counts into `target`.
  void run(const SceneFrame& frame, const CrossingGeometry& geometry, const gpu::Texture& target,
           gpu::PassTimer& timer) override;

  // crossings (drawn into the lists), fragments (shaded by the last draw of
  // the triangles; 0 without pipeline statistics), redraws (the pool grown
  // this frame), loop_limited (pixels llvmpipe's loop limit cut short) and
  // passes (of the resolve: more than one where that limit was met).
  std::vector<std::pair<std::string, double>> stats() const override;

private:
  const gpu::Buffer& upload(std::span<const CountedTriangle> triangles);
  void list_crossings(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count);
  void draw(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count);
  void resolve(const SceneFrame& frame, const EyeCounts& eye, const gpu::Texture& target);
  void resolve_in_passes(const SceneFrame& frame, const gpu::Program& program, const gpu::Texture& target);
  void allocate_pool(size_t nodes);
  std::string defines() const;

  double capacity_per_pixel_;
  int samples_;
  gpu::Buffer triangles_, nodes_, node_count_;
  size_t triangle_capacity_ = 0, node_capacity_ = 0;
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
