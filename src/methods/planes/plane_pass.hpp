#pragma once
// The planes pass (Dobashi 2000 §5): per light, n virtual planes parallel to
// the image plane from the eye to the far end of the light's lit region,
// drawn as instances of one lattice mesh with the depth test against the
// G-buffer, clipped to the light's influence volume, blended additively into
// the RGBA32F airlight target.
#include "methods/kit/scene_frame.hpp"
#include "methods/kit/light_bounds.hpp"
#include "methods/kit/noise.hpp"

#include <airlight/scene.hpp>
#include <airlight/settings.hpp>
#include <string>
#include <vector>

namespace airlight::methods {

std::vector<SettingSpec> plane_settings();

struct PlaneSettings {
  int planes = 100;              // n per light
  double spacing = 0.0;          // dz in metres of view depth; 0: from n
  int lattice = 0;               // cells per side of the lattice mesh; 0: ξ per fragment
  kit::Jitter jitter = kit::Jitter::none;
  bool lit_sampling = true;      // sample each slab's lit piece, else the slab (Dobashi)
  bool clip = true;              // clip planes to the influence volume

  static PlaneSettings from(const Settings& settings);
};

class PlanePass {
public:
  explicit PlanePass(PlaneSettings settings) : settings_(std::move(settings)) {}

  // Program, noise tile, lattice mesh, and each light's volume (rays cast
  // through the scene on the CPU); needs a current context.
  void prepare(const Scene& scene);

  // L_air into `target`; the frame must be bound (SceneFrame::bind).
  void run(const kit::SceneFrame& frame, const gpu::Texture& target);

  double planes_drawn() const { return planes_drawn_; }
  // Of the last run: lights whose lit region was traced again, and its seconds.
  const kit::LitRegions& regions() const { return regions_; }
  // Fragment shader invocations of the last run (the planes' fragments that
  // passed the depth test and were shaded); -1 without ARB_pipeline_statistics_query.
  double fragments() const { return fragments_; }

private:
  struct Slabs {
    int count = 0;
    float dz = 0.0f;
  };
  Slabs slabs(const kit::LightBounds& volume) const;
  std::string defines(int light) const;
  void draw_light(const kit::SceneFrame& frame, int light, const kit::LightBounds& volume);

  PlaneSettings settings_;
  geometry::CameraBasis camera_;
  double far_ = 0.0;
  float cos_edge_ = 1.0f;  // the smallest cos(ray, forward) in the image
  kit::LitRegions regions_;
  gpu::Texture noise_;
  gpu::VertexArray mesh_;
  gpu::Buffer indices_;
  gpu::Framebuffer fbo_;
  gpu::Query invocations_;
  int index_count_ = 0;
  double planes_drawn_ = 0.0, fragments_ = -1.0;
};

}  // namespace airlight::methods
