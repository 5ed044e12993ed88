#pragma once
// Reduced resolution for the methods that evaluate the airlight per pixel
// (docs/design.md §3): the method renders on a grid 1/2 or 1/4 as fine per
// axis, whose distance is a min/max downsample of the G-buffer's, and the
// result comes back to the full grid by joint bilateral upsampling guided by
// the full-resolution distance, as engines do. Where every coarse neighbour
// lies across a depth edge the weights fail; so do the pixels near the image
// of a point or spot light, where L_air changes by large factors from pixel
// to pixel (its 1/h peak, a gobo's stripes converging on it) and no coarse
// neighbour stands for a pixel. Those pixels (and the `halo` around them that
// the method's own result there reads) are rendered again on the full grid by
// the same method and copied in.
#include "gpu/growing_buffer.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <glm/vec2.hpp>

#include <airlight/settings.hpp>
#include <string>
#include <vector>

namespace airlight::kit {

// The settings `scale` and `upsample`, for a method to put after its own.
std::vector<SettingSpec> resolution_settings();

struct ResolutionSettings {
  int divisor = 1;        // the full grid's pixels per coarse pixel, per axis: 1, 2 or 4
  bool bilateral = true;  // false: plain bilinear upsampling, nothing recomputed
  // From a method's settings: divisor 1 where the method declares no `scale`.
  static ResolutionSettings from(const Settings& settings);
};

// What a method's passes need of the grid of the pixels it recomputes
// (GpuMethod::recompute_halo, draws_on_grid).
struct RecomputeGrid {
  int halo = 0;         // pixels (Chebyshev) around each failed one
  bool marked = false;  // a distance of −1 at the pixels left out
};

class ReducedResolution {
public:
  explicit ReducedResolution(ResolutionSettings settings) : settings_(settings) {}
  bool reduces() const { return settings_.divisor > 1; }

  // The coarse grid's distance by min/max downsampling ("downsample"); the
  // frame on that grid, bound. Then the method renders into coarse_target().
  void reduce(SceneFrame& frame, PassTimer& timer);
  const Texture& coarse_target() const { return coarse_airlight_; }

  // The coarse airlight upsampled into `target` on the G-buffer's grid
  // ("upsample"). With bilateral upsampling, the frame then on the grid of
  // the pixels to recompute — each failed pixel and the `grid`'s halo around
  // it — bound, for the method to render into recompute_target(); returns
  // whether that is wanted.
  bool upsample(SceneFrame& frame, const Texture& target, RecomputeGrid grid, PassTimer& timer);
  const Texture& recompute_target() const { return recomputed_; }
  // The recomputed pixels copied into `target` ("merge"); the frame back on
  // the G-buffer's grid, bound.
  void merge(SceneFrame& frame, const Texture& target, PassTimer& timer);

  // The fraction of the last frame's pixels whose weights failed (reads a
  // counter back: waits for the GPU).
  double recomputed_fraction() const;

private:
  void allocate(const SceneFrame& frame);
  int upload_light_images(const SceneFrame& frame);
  void bilateral_upsample(const SceneFrame& frame, RecomputeGrid grid);
  void use_recompute_grid(SceneFrame& frame, RecomputeGrid grid);
  void list_halo(RecomputeGrid grid);
  std::string upsample_defines() const;

  ResolutionSettings settings_;
  int width_ = 0, height_ = 0, coarse_width_ = 0, coarse_height_ = 0;
  Texture coarse_distance_, coarse_airlight_, recomputed_;
  Buffer failed_list_;  // the failed pixels (frame/pixel_list.glsl)
  // Made on first use: the failed pixels' distance (−1 elsewhere), for a
  // marked grid; for a halo, a flag a 2×2 block where one failed, the
  // recomputation's pixels and, marked, their distance.
  Texture failed_, failed_blocks_, halo_distance_;
  Buffer halo_list_;
  gpu::GrowingBuffer<glm::vec2> light_images_;
};

}  // namespace airlight::kit
