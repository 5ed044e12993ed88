#include "methods/kit/planes/plane_method.hpp"
#include "methods/kit/method/registry.hpp"

namespace airlight::methods {
namespace {

MethodInfo planes_method() {
  return {"planes", "Dobashi 2000",
          "virtual planes parallel to the image plane, one set per light from the eye to the far end of its lit "
          "region, clipped to the light's influence volume, depth-tested against the scene; each fragment adds "
          "I(θ,φ)·ξ·V·Δt (light map, ξ per fragment or on a lattice mesh, shadow-map test) by additive blending "
          "into a float target",
          kit::gpu_settings(kit::plane_settings()),
          kit::create<kit::PlaneMethod>(kit::PlaneCut::none),
          160, kit::gpu_memory(), {},
          {kit::high_quality_trial({"planes=1024", "shadow_resolution=2048"},
            "1024 planes per light through its lit region and 2048² maps: the slabs' sampling is what is "
            "left")}, {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(3, planes_method);

}  // namespace airlight::methods
