#pragma once
// Interleaved sampling's separable sum (Tóth 2009 §4.1; gather.comp.glsl): a
// horizontal then a vertical pass, each adding M consecutive pixels, optionally
// leaving out neighbours across silhouettes (depth-aware).
#include "gpu/program.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <string>

namespace airlight::methods {

struct GatherSettings {
  int block = 4;                 // M
  bool depth_aware = true;
  float depth_threshold = 0.1f;  // relative distance difference that excludes a neighbour
  bool normalized = false;       // partial sums come divided by the light guide (kit::MarchSettings)
  float guard = 0.0f;            // k: clamp to the own estimate ± k standard errors (0: no guard)
};

class GatherPass {
public:
  explicit GatherPass(GatherSettings settings) : settings_(settings) {}

  // Replaces each pixel of `image` (RGBA32F of the frame's size) by the sum over
  // its M×M window, times the pixel's light guide from `guide` when normalized,
  // clamped by the march's `spread` when guarded; the frame must be bound
  // (SceneFrame::bind).
  void run(const kit::SceneFrame& frame, const gpu::Texture& image, const gpu::Texture& guide,
           const gpu::Texture& spread);
  // Compiles run()'s two programs here, where they run, while the march runs
  // in the worker's context: each dispatched once over no pixels with the
  // run's textures (SceneFrame::warm_pixels), then the frame bound again.
  void warm(const kit::SceneFrame& frame, const gpu::Texture& image, const gpu::Texture& guide,
            const gpu::Texture& spread);

private:
  void size_for(const kit::SceneFrame& frame);
  std::string defines(const kit::SceneFrame& frame, bool vertical) const;
  void bind(const gpu::Program& program, const gpu::Texture& from, const gpu::Texture& to) const;
  void pass(const kit::SceneFrame& frame, const gpu::Texture& from, const gpu::Texture& to, bool vertical);

  GatherSettings settings_;
  gpu::Texture rows_;  // the horizontal pass's output
  int width_ = 0, height_ = 0;
  std::string warmed_;  // the frame defines warm() compiled for
};

}  // namespace airlight::methods
