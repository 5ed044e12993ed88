#pragma once
// Nilsson 2008 §3.2 (accumulate=signed): every counted face's ±Γ(0 → z) added
// into the cleared target by blending (signed.frag.glsl), instead of Γ over
// lit intervals: the sum cancels large terms where Γ is large.
#include "gpu/growing_buffer.hpp"
#include "methods/kit/counting/crossing_geometry.hpp"

namespace airlight::methods {

class SignedFaces final : public kit::CrossingPass {
public:
  void prepare() override;
  // Timed as "airlight"; the geometry's eye counts are not needed.
  void run(const kit::SceneFrame& frame, const kit::CrossingGeometry& geometry, const gpu::Texture& target,
           gpu::PassTimer& timer) override;
  std::vector<std::pair<std::string, double>> stats() const override { return {}; }

private:
  gpu::Framebuffer fbo_;
  gpu::VertexArray no_vertices_;
  gpu::GrowingBuffer<kit::CountedTriangle> faces_;  // a geometry's from the CPU
};

}  // namespace airlight::methods
