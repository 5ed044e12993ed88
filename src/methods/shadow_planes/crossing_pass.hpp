#pragma once
// The shadow planes of every caster and light for one frame (Biri §5.1), and
// their crossings with each pixel's view ray in per-pixel lists
// (crossings.vert/.frag.glsl) for the resolve to walk.
#include "geometry/shadow_edges.hpp"
#include "gpu/gl.hpp"
#include "methods/kit/scene_frame.hpp"

#include <airlight/scene.hpp>
#include <string>
#include <utility>
#include <vector>

namespace airlight::methods {

class CrossingPass {
public:
  // `capacity`: crossings per pixel the node pool holds at first; a frame
  // with more grows it and draws the planes again (never drops a crossing).
  explicit CrossingPass(double capacity) : capacity_per_pixel_(capacity) {}

  // Welds each shadow caster and finds its edges' triangles, once per scene.
  void prepare(const Scene& scene);

  // The frame's planes (CPU, timed as build_s) and their crossings (GPU); the
  // frame must be bound. Afterwards heads() and the node pool hold each
  // pixel's list, and eye_counts() each light's shadow count at the eye.
  void run(const kit::SceneFrame& frame);

  // Binds the plane buffer and the node pool to their storage bindings.
  void bind() const;
  const gpu::Texture& heads() const { return heads_; }
  const std::vector<int>& eye_counts() const { return eye_counts_; }

  // "#define BINDING_PLANES n" and the others of crossings.glsl.
  static std::string defines();

  // Counters for the report: planes, crossings, build_s, redraws, and per
  // caster whether it is closed (its planes are its silhouettes) or open (the
  // edges of its triangles' own volumes).
  std::vector<std::pair<std::string, double>> stats() const;

private:
  struct Caster {
    int mesh = 0;
    geometry::CasterTopology topology;
    std::vector<glm::vec3> world;  // this frame's welded positions
  };
  void build_planes(const FrameInputs& inputs);
  void draw(const kit::SceneFrame& frame);
  void allocate_pool(size_t nodes);

  double capacity_per_pixel_;
  std::vector<Caster> casters_;
  std::vector<geometry::ShadowPlane> planes_;
  std::vector<int> plane_lights_;  // per plane
  std::vector<int> eye_counts_;
  gpu::Buffer plane_buffer_, nodes_, node_count_;
  size_t plane_capacity_ = 0, node_capacity_ = 0;
  gpu::Texture heads_;
  gpu::Framebuffer fbo_;
  gpu::VertexArray no_vertices_;
  int width_ = 0, height_ = 0;
  double build_s_ = 0.0;
  unsigned crossings_ = 0;
  int redraws_ = 0;
  int silhouette_edges_ = 0, boundary_edges_ = 0, loops_ = 0;
};

}  // namespace airlight::methods
