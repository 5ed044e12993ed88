#include "methods/kit/counting/crossing_method.hpp"
#include "methods/kit/method/memory_needs.hpp"
#include "methods/kit/method/registry.hpp"
#include "methods/shadow_planes/silhouettes.hpp"

#include <memory>

namespace airlight::methods {

namespace {

// Up to two counted triangles per caster edge and light (silhouettes.cpp), and
// the crossing pool beyond its default.
std::vector<MemoryNeed> shadow_planes_memory(const Scene& scene, const Settings& s, int width, int height) {
  const double triangles = kit::caster_triangles(scene), lights = static_cast<double>(scene.lights.size());
  std::vector<MemoryNeed> needs = kit::crossing_pool_needs(s, width, height);
  needs.push_back(kit::counted_triangle_need("the shadow planes of " + kit::counted(triangles, "caster triangle") +
                                                 " and " + kit::counted(lights, "light") + " (2 triangles per edge)",
                                             6.0 * triangles * lights));
  return needs;
}

// max_edges' default: the sieve of separate triangles (scripts/million-triangles),
// every edge a plane, renders within 120 s and 4 GiB at 256×192 up to about this many.
constexpr double max_edges = 1e6;

// Biri, Arquès & Michelin 2006: the casters' shadow planes (silhouettes.cpp),
// their crossings with each pixel's ray and Γ over each light's lit intervals
// (the kit's lit-interval pass). No shadow map: the shadows are the casters' own edges.
MethodInfo shadow_planes_method() {
  using T = SettingSpec::Type;
  std::vector<SettingSpec> own = kit::lit_interval_settings();
  own.push_back({"max_edges", T::integer, max_edges, 1, 1e9, {},
                 "the most edges the casters' triangles may have (3 a triangle), summed over the lights: each may be "
                 "a shadow plane drawn across the image (every one of an open mesh of separate triangles), so a larger "
                 "scene is refused before any work"});
  return {"shadow_planes", "Biri 2006",
          "exact volumetric shadows from the casters' silhouette edges (every triangle edge of an open caster) "
          "extruded away from each light to infinity; per pixel the planes' crossings with the view ray, sorted "
          "and counted from the eye's count, give each light's lit intervals, over which the closed-form Γ is "
          "summed, piece by piece through bounded volumes (Biri §5.2); gobos and the light's leg through other "
          "volumes by a sampled ratio",
          kit::per_pixel_settings(std::move(own)),
          [](const Settings& s) { return std::make_unique<kit::CrossingMethod>(s, std::make_unique<Silhouettes>()); },
          224, kit::gpu_memory(shadow_planes_memory), {.caster_triangles = true},
          {{"exact", {"samples=512"}, Trial::Measure::worst_pixel, 0.02,
            "exact shadows from the casters' own triangles and Γ in closed form (512 points per interval where "
            "there is none: gobos, the simplified model): issue 25's bound for the exact methods"}, kit::reduced_trial("shadow_planes")},
          {{"max_edges", "caster triangle edges summed over its lights",
            "each edge may be a shadow plane, and the planes are drawn across the image",
            [](const Scene& scene) {
              return 3.0 * kit::caster_triangles(scene) * static_cast<double>(scene.lights.size());
            }}}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(5, shadow_planes_method);

}  // namespace airlight::methods
