#include "methods/kit/plane_method.hpp"
#include "methods/kit/registry.hpp"

#include <memory>

namespace airlight::methods {
namespace {

MethodInfo planes_method() {
  return {"planes", "Dobashi 2000",
          "virtual planes parallel to the image plane, one set per light from the eye to the far end of its lit "
          "region, clipped to the light's influence volume, depth-tested against the scene; each fragment adds "
          "I(θ,φ)·ξ·V·Δt (light map, ξ per fragment or on a lattice mesh, shadow-map test) by additive blending "
          "into a float target",
          kit::gpu_settings(kit::plane_settings()),
          [](const Settings& s) { return std::make_unique<kit::PlaneMethod>(s, kit::PlaneRegions::none); },
          160, kit::gpu_memory(), {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(3, planes_method);

}  // namespace airlight::methods
