#include "methods/kit/planes/plane_method.hpp"
#include "methods/kit/method/registry.hpp"

namespace airlight::methods {
namespace {

// Nilsson 2008 §5.3, Method 1: planes cut by the regions of the casters'
// bounding volumes (kit/slab_pieces.hpp, kit/plane_pass.cpp draw_pieces).
MethodInfo hybrid_clip_method() {
  return {"hybrid_clip", "Nilsson 2008 §5.3",
          "the planes cut per light by the beam trees of the casters' bounding volumes: unlit parts never "
          "rasterized, fully lit parts sampled without the shadow-map test, uncertain parts with it; with "
          "sampling=plane the image of planes, from fewer fragments",
          kit::gpu_settings(kit::plane_settings(true)),
          kit::create<kit::PlaneMethod>(kit::PlaneCut::clip),
          160, kit::gpu_memory(kit::slab_piece_needs), {.caster_triangles = true},
          {kit::high_quality_trial({"planes=1024", "shadow_resolution=2048"},
            "1024 planes per light clipped by the bounding volumes' beam trees, 2048² maps: the slabs' "
            "sampling is what is left")}, {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(7, hybrid_clip_method);

}  // namespace airlight::methods
