#include "methods/kit/planes/plane_method.hpp"
#include "methods/kit/method/registry.hpp"

namespace airlight::methods {
namespace {

// Nilsson 2008 §5.4, Method 2: Γ over the fully lit region, the planes' samples
// over the uncertain one (kit/plane_pass.cpp draw_pieces, planes.frag.glsl
// FULLY_LIT_GAMMA). The regions are taken slab by slab at the planes' middles,
// so the two parts tile the lit region without a seam (docs/decisions.md).
MethodInfo hybrid_method() {
  return {"hybrid", "Nilsson 2008 §5.4",
          "the planes cut per light by the beam trees of the casters' bounding volumes: unlit parts never "
          "rasterized, each fully lit slab integrated exactly by the closed-form Γ, uncertain slabs sampled with "
          "the shadow-map test",
          kit::gpu_settings(kit::plane_settings(true)),
          kit::create<kit::PlaneMethod>(kit::PlaneCut::gamma),
          160, kit::gpu_memory(kit::slab_piece_needs), {.caster_triangles = true},
          {kit::high_quality_trial({"planes=1024", "shadow_resolution=2048"},
            "1024 planes per light, fully lit slabs in closed form, 2048² maps: the partly lit slabs' "
            "sampling is what is left")}, {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(8, hybrid_method);

}  // namespace airlight::methods
