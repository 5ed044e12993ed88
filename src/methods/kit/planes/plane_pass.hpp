#pragma once
// The planes pass (Dobashi 2000 §5): per light, n virtual planes parallel to
// the image plane from the eye to the far end of the light's lit region,
// drawn as instances of one lattice mesh with the depth test against the
// G-buffer, clipped to the light's influence volume, blended additively into
// the RGBA32F airlight target. Shared by planes and by Nilsson's hybrids
// (§5.3–5.4), which draw each plane as its fully lit and uncertain parts
// (slab_pieces.hpp) instead of the lattice.
#include "gpu/growing_buffer.hpp"
#include "gpu/query.hpp"
#include "methods/kit/planes/light_bounds.hpp"
#include "methods/kit/sampling/noise.hpp"
#include "methods/kit/frame/scene_frame.hpp"
#include "methods/kit/planes/slab_pieces.hpp"

#include <airlight/scene.hpp>
#include <airlight/settings.hpp>
#include <string>
#include <vector>

namespace airlight::kit {

// How the planes are drawn: whole (Dobashi), or cut into pieces by the light's
// regions of space (geometry::LightRegions over the casters' bounding volumes:
// fully lit, uncertain, unlit; slab_pieces.hpp), the unlit pieces left out and the fully lit parts sampled
// without the shadow test (Nilsson's Method 1, clip) or integrated by Γ
// (his Method 2, gamma).
enum class PlaneCut { none, clip, gamma };

// Every setting of the planes, or (cut) those that keep a plane's sample
// at the middle of its slab: no lattice, no jitter.
std::vector<SettingSpec> plane_settings(bool cut = false);

// The hybrids' slab pieces (SlabPieces, the trees one light at a time): the
// planes' polygons cut by the casters' bounding volumes, on the CPU and the GPU.
std::vector<MemoryNeed> slab_piece_needs(const Scene& scene, const Settings& settings, int width, int height);

struct PlaneSettings {
  int planes = 100;              // n per light
  double spacing = 0.0;          // dz in metres of view depth; 0: from n
  int lattice = 0;               // cells per side of the lattice mesh; 0: ξ per fragment
  Jitter jitter = Jitter::none;
  bool lit_sampling = true;      // sample each slab's lit piece, else the slab (Dobashi)
  bool clip = true;              // clip planes to the influence volume
  PlaneCut cut = PlaneCut::none;

  static PlaneSettings from(const Settings& settings, PlaneCut cut = PlaneCut::none);
};

class PlanePass {
public:
  explicit PlanePass(PlaneSettings settings) : settings_(std::move(settings)) {}

  // Program, noise tile, lattice mesh, and each light's volume (rays cast
  // through the scene on the CPU); needs a current context.
  void prepare(const Scene& scene);

  // The frame's planes on the CPU — each light's slabs and, for the hybrids,
  // its slab pieces — and the start of linking the programs that will draw
  // them (gpu::link_ahead), before the frame's passes (GpuMethod::link_ahead):
  // which parts a light draws depends on its pieces, and the GLSL compiler
  // then runs beside the frame's earlier passes.
  void plan(const SceneFrame& frame);
  // L_air into `target` as planned; the frame must be bound (SceneFrame::bind).
  void run(const SceneFrame& frame, const gpu::Texture& target);

  // Of the last run: planes, fragment shader invocations (the planes' fragments
  // that passed the depth test and were shaded, of the newest run the GPU has
  // finished, read without waiting; -1 before the first or without
  // ARB_pipeline_statistics_query), the lights whose lit region was traced
  // again and its seconds, and when cut its pieces' polygons and trees.
  std::vector<std::pair<std::string, double>> stats() const;

private:
  struct Slabs {
    int count = 0;
    float dz = 0.0f;
  };
  Slabs slabs(const LightBounds& volume) const;
  float reach(const Slabs& s) const;
  enum class Part { lattice, fully_lit, uncertain, cut_slabs };
  // A light's planes this frame: its slabs (none where it lights nothing in
  // view), clip planes, and the hybrids' pieces.
  struct LightPlan {
    Slabs slabs;
    std::vector<glm::vec4> clip;
    SlabPieces::Pieces pieces;
  };
  LightPlan plan_light(const SceneFrame& frame, int light, const LightBounds& volume);
  std::vector<Part> parts(const LightPlan& plan) const;  // what the light draws, in order
  std::string defines(const SceneFrame& frame, int light, Part part) const;
  static const char* vertex_stage(Part part);
  void draw(const SceneFrame& frame, int light, Part part, const LightPlan& plan);
  void upload(const std::vector<PieceVertex>& vertices);

  PlaneSettings settings_;
  geometry::CameraBasis camera_;
  double far_ = 0.0;
  float cos_edge_ = 1.0f;  // the smallest cos(ray, forward) in the image
  FrameLightBounds light_bounds_;
  SlabPieces slab_pieces_;
  std::vector<LightPlan> plans_;  // per light, by plan()
  gpu::Texture noise_;
  gpu::VertexArray mesh_, piece_mesh_, no_vertices_;
  gpu::Buffer indices_;
  gpu::GrowingBuffer<PieceVertex> piece_vertices_{2};
  gpu::Framebuffer fbo_;
  gpu::InvocationCounter invocations_;
  int index_count_ = 0;
  double planes_drawn_ = 0.0;
};

}  // namespace airlight::kit
