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
#include "gpu/growing_buffer.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/counting/counted_draw.hpp"
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
class LitIntervalPass final : public CrossingPass {
public:
  // eye_planes: whether the geometry's eye counts may hold planes through
  // the eye (CrossingGeometry::has_eye_planes).
  LitIntervalPass(const Settings& settings, bool eye_planes);

  void prepare() override;
  // The crossings' draw and the resolve (the cull waits: it runs only when there are triangles).
  void link_ahead(const SceneFrame& frame, const gpu::Texture& target) override;

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
  void list_crossings(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count);
  void draw(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count);
  // The resolve's images by their names, for the worker's thread (SceneFrame::warm_pixels).
  struct ResolveImages {
    GLuint target, heads, progress;  // progress: 0 unless it runs in passes
    void bind() const;
  };
  ResolveImages resolve_images(const gpu::Texture& target) const;
  void size_for(const SceneFrame& frame);
  void resolve(const SceneFrame& frame, const gpu::Program& program, const EyeCounts& eye, const gpu::Texture& target);
  void resolve_in_passes(const SceneFrame& frame, const gpu::Program& program);
  void allocate_pool(size_t nodes);
  std::string defines() const;
  std::string resolve_defines(const SceneFrame& frame) const;
  std::string crossings_defines(const SceneFrame& frame) const;

  double capacity_per_pixel_;
  int samples_;
  bool eye_planes_;  // EYE_PLANES
  gpu::GrowingBuffer<CountedTriangle> triangles_;  // a geometry's from the CPU
  gpu::Buffer nodes_, node_count_;
  size_t node_capacity_ = 0;
  gpu::Texture heads_;
  CountedDraw counted_draw_;
  int width_ = 0, height_ = 0;
  unsigned crossings_ = 0;
  int redraws_ = 0;
  GLuint loop_limited_ = 0;
  bool loop_limit_ = false;         // llvmpipe: the resolve runs in passes (LOOP_LIMIT)
  int passes_ = 1;                  // of the resolve (more on llvmpipe where its loop limit bites)
  gpu::Texture progress_;           // per pixel: intervals summed, or finished (LOOP_LIMIT), sized with heads_
};

}  // namespace airlight::kit
