#include "methods/beam_volumes/lit_pyramids.hpp"
#include "methods/beam_volumes/signed_faces.hpp"
#include "methods/kit/counting/crossing_method.hpp"
#include "methods/kit/method/memory_needs.hpp"
#include "methods/kit/method/registry.hpp"

#include <memory>

namespace airlight::methods {
namespace {

// Nilsson 2008 §3.2: the pyramids between each light and its beam tree's
// visible set (lit_pyramids.cpp), then per pixel Γ over each light's lit
// intervals — counted from their faces' crossings by the kit's lit-interval
// pass (accumulate=intervals), or Nilsson's ±Γ(0 → z) of each face blended
// into a float target (accumulate=signed, signed_faces.hpp). No shadow map.
enum class Accumulate { intervals, signed_faces };  // the `accumulate` setting's choices, in order

std::unique_ptr<Method> beam_volumes(const Settings& s) {
  auto pyramids = std::make_unique<LitPyramids>();
  if (s.option<Accumulate>("accumulate") == Accumulate::intervals)
    return std::make_unique<kit::CrossingMethod>(s, std::move(pyramids));
  return std::make_unique<kit::CrossingMethod>(s, std::move(pyramids), std::make_unique<SignedFaces>());
}

// Per light, the beam tree over every caster triangle, its visible pieces and
// their pyramids' faces, about four a triangle in one buffer (measured:
// docs/decisions.md "Memory for settings"); the crossing pool beyond its default.
std::vector<MemoryNeed> beam_volumes_memory(const Scene& scene, const Settings& s, int width, int height) {
  constexpr double bytes_per_triangle = 2500.0;
  const double triangles = kit::caster_triangles(scene), lights = static_cast<double>(scene.lights.size());
  std::vector<MemoryNeed> needs = kit::crossing_pool_needs(s, width, height);
  needs.push_back({"",
                   "the beam trees and pyramids of " + kit::counted(triangles, "caster triangle") + " and " +
                       kit::counted(lights, "light") + " (about 2.5 KB per triangle and light)",
                   bytes_per_triangle * triangles * lights, 4.0 * triangles * lights * sizeof(kit::CountedTriangle)});
  return needs;
}

// max_triangles' default: the sieve of separate triangles (scripts/million-triangles)
// renders within 120 s and 4 GiB at 256×192 up to about this many.
constexpr double max_triangles = 200000;

MethodInfo beam_volumes_method() {
  using T = SettingSpec::Type;
  std::vector<SettingSpec> own = kit::lit_interval_settings();
  own.push_back({"accumulate", T::choice, 0, 0, 0, {"intervals", "signed"},
                 "intervals = Γ over each lit interval, counted from the pyramids' crossings with the view ray (no "
                 "cancellation); signed = Nilsson's: each face adds (back) or subtracts (front) Γ(0 → z) in a float "
                 "target, which cancels large terms where Γ is large, near a light in view"});
  own.push_back({"max_triangles", T::integer, max_triangles, 1, 1e9, {},
                 "the most caster triangles a scene may have, summed over its lights (each light's beam tree holds them "
                 "all and is built on the CPU every frame): a larger scene is refused before any work"});
  return {"beam_volumes", "Nilsson 2008 §3.2, ch. 4",
          "exact volumetric shadows from a beam tree per light (a BSP tree of planes through the light, any "
          "polygon order): the pyramids between the light and the polygons it sees first, backplate included, "
          "bound its lit region; per pixel the closed-form Γ summed over the lit intervals",
          kit::per_pixel_settings(std::move(own)), beam_volumes,
          224, kit::gpu_memory(beam_volumes_memory), {.caster_triangles = true},
          {{"exact", {"samples=512"}, Trial::Measure::worst_pixel, 0.02,
            "exact shadows from the beam trees of the casters' triangles and Γ in closed form (512 points per "
            "interval where there is none): issue 25's bound for the exact methods"}, kit::reduced_trial("beam_volumes")},
          {{"max_triangles", "caster triangles summed over its lights",
            "each light's beam tree holds every caster triangle and is built on the CPU every frame",
            [](const Scene& scene) {
              return kit::caster_triangles(scene) * static_cast<double>(scene.lights.size());
            }}}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(6, beam_volumes_method);

}  // namespace airlight::methods
