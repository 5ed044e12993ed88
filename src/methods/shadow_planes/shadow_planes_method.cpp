#include "methods/kit/gpu_method.hpp"
#include "methods/kit/lit_interval_pass.hpp"
#include "methods/kit/memory_needs.hpp"
#include "methods/shadow_planes/silhouettes.hpp"

#include "methods/kit/registry.hpp"

#include <memory>

namespace airlight::methods {

namespace {

// Biri, Arquès & Michelin 2006: the casters' shadow planes (silhouettes.cpp),
// their crossings with each pixel's ray and Γ over each light's lit intervals
// (the kit's lit-interval pass). No shadow map: the shadows are the casters' own edges.
class ShadowPlanes final : public kit::GpuMethod {
public:
  explicit ShadowPlanes(const Settings& s) : GpuMethod(s), intervals_(s) {}

private:
  void prepare_airlight(const Scene& scene) override {
    silhouettes_.prepare(scene);
    intervals_.prepare();
  }

  void render_airlight(const kit::SceneFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    silhouettes_.build(frame.inputs());
    intervals_.run(frame, silhouettes_.triangles(), silhouettes_.eye_counts(), target, timer);
  }

  bool uses_shadow_maps() const override { return false; }

  std::vector<std::pair<std::string, double>> stats() const override {
    auto s = silhouettes_.stats();
    const auto more = intervals_.stats();
    s.insert(s.end(), more.begin(), more.end());
    return s;
  }

  Silhouettes silhouettes_;
  kit::LitIntervalPass intervals_;
};

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

MethodInfo shadow_planes_method() {
  return {"shadow_planes", "Biri 2006",
          "exact volumetric shadows from the casters' silhouette edges (every triangle edge of an open caster) "
          "extruded away from each light to infinity; per pixel the planes' crossings with the view ray, sorted "
          "and counted from the eye's count, give each light's lit intervals, over which the closed-form Γ is "
          "summed, piece by piece through bounded volumes (Biri §5.2); gobos and the light's leg through other "
          "volumes by a sampled ratio",
          kit::gpu_settings(kit::lit_interval_settings()),
          [](const Settings& s) { return std::make_unique<ShadowPlanes>(s); },
          224, kit::gpu_memory(shadow_planes_memory), {.caster_triangles = true},
          {{"exact", {"samples=512"}, Trial::Measure::worst_pixel, 0.02,
            "exact shadows from the casters' own triangles and Γ in closed form (512 points per interval where "
            "there is none: gobos, the simplified model): issue 25's bound for the exact methods"}}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(5, shadow_planes_method);

}  // namespace airlight::methods
