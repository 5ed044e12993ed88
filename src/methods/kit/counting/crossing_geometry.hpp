#pragma once
// Geometry whose crossings with the view rays are counted (docs/design.md §3):
// per frame, triangles that bound each light's lit region (CountedTriangle)
// and each light's count at the eye, which a CrossingPass turns into L_air —
// shadow_planes' silhouettes and beam_volumes' lit pyramids (CasterCrossings,
// built on the CPU from the casters), the light volume mesh (built on the GPU
// from the shadow maps). A method of such geometry is a CrossingMethod.
#include "gpu/gl.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/counting/counted_triangles.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace airlight::kit {

// A frame's counted triangles: on the CPU, or the first `count` records of a
// GPU buffer (on_gpu not null).
struct CountedTriangles {
  std::span<const CountedTriangle> on_cpu;
  const gpu::Buffer* on_gpu = nullptr;
  size_t count = 0;
  size_t size() const { return on_gpu ? count : on_cpu.size(); }
};

class CrossingGeometry {
public:
  virtual ~CrossingGeometry() = default;
  // What depends on the scene alone; the context is current.
  virtual void prepare(const Scene& scene) = 0;
  // This frame's triangles and eye counts, after its shadow maps are drawn; GPU work timed with `timer`.
  virtual void build(const SceneFrame& frame, gpu::PassTimer& timer) = 0;
  // Starts linking what build() will use for this frame (GpuMethod::link_ahead).
  virtual void link_ahead(const SceneFrame& frame) { (void)frame; }
  virtual CountedTriangles triangles() const = 0;
  virtual EyeCounts eye_counts() const = 0;
  // Whether eye_counts() may hold planes through the eye (EyeCounts::planes):
  // the lit-interval pass compiles their test only then.
  virtual bool has_eye_planes() const = 0;
  // Whether the frame must draw the lights' shadow maps for build().
  virtual bool uses_shadow_maps() const = 0;
  // Counters for the report, the build's time among them.
  virtual std::vector<std::pair<std::string, double>> stats() const = 0;
};

// What turns a geometry's triangles and eye counts into L_air: LitIntervalPass
// (Γ over the lit intervals their crossings bound), or a method's own.
class CrossingPass {
public:
  virtual ~CrossingPass() = default;
  virtual void prepare() = 0;  // needs a current context
  // Starts linking what run() will use for this frame (GpuMethod::link_ahead).
  virtual void link_ahead(const SceneFrame& frame, const gpu::Texture& target) {
    (void)frame;
    (void)target;
  }
  // L_air into `target` (RGBA32F at the frame's size); the frame must be bound.
  virtual void run(const SceneFrame& frame, const CrossingGeometry& geometry, const gpu::Texture& target,
                   gpu::PassTimer& timer) = 0;
  virtual std::vector<std::pair<std::string, double>> stats() const = 0;
};

// Counted triangles built on the CPU every frame from the scene's shadow
// casters (Mesh::casts_shadows), without shadow maps; the build, with no GL
// work, is timed as the stat build_s and as the pass "build": it is part of
// what the method adds to a frame (bench's own time).
class CasterCrossings : public CrossingGeometry {
public:
  void prepare(const Scene& scene) final;
  // The frame's triangles and eye counts (no GL).
  void build(const FrameInputs& inputs);
  void build(const SceneFrame& frame, gpu::PassTimer& timer) override {
    gpu::ScopedPass pass(timer, "build");
    build(frame.inputs());
  }
  CountedTriangles triangles() const final { return {triangles_, nullptr, triangles_.size()}; }
  EyeCounts eye_counts() const final { return eye_; }
  bool has_eye_planes() const final { return true; }  // take_planes_at_eye
  bool uses_shadow_maps() const final { return false; }

protected:
  // What the casters (indices into Scene::meshes and FrameInputs::transforms) fix.
  virtual void prepare_casters(const Scene& scene, const std::vector<int>& casters) = 0;
  // The frame's triangles_ (cleared) and eye_.
  virtual void add_triangles(const FrameInputs& inputs) = 0;

  std::vector<CountedTriangle> triangles_;
  EyeCounts eye_;
  double build_s_ = 0.0;
};

}  // namespace airlight::kit
