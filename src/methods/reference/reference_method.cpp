#include "methods/kit/method/registry.hpp"
#include "reference/reference.hpp"

#include <airlight/error.hpp>

namespace airlight::methods {
namespace {

// The CPU ground truth renders each frame's posed scene from scratch (Embree's
// scene is rebuilt per frame: the reference is never the fast path).
class ReferenceMethod final : public Method {
public:
  explicit ReferenceMethod(const Settings& s) : settings_{s.real("rel_tol"), s.integer("min_segments")} {}

  void prepare(const Scene& scene) override { scene_ = scene; }

  void render_frame(const FrameInputs& inputs) override {
    reference::Images r = reference::render(posed_scene(scene_, inputs), inputs.width, inputs.height, settings_);
    images_ = FrameImages{};
    images_.airlight = std::move(r.airlight);
    images_.surface = std::move(r.surface);
    images_.stats = {{"shadow_rays", static_cast<double>(r.shadow_rays)}};
    rendered_ = true;
  }

  FrameImages read_back() const override {
    if (!rendered_) throw Failure("read_back() before render_frame()");
    return images_;
  }

private:
  reference::Settings settings_;
  Scene scene_;
  FrameImages images_;
  bool rendered_ = false;
};

// Embree's BVH over every triangle, the prepared copy of the scene and each
// frame's posed one (measured per triangle: docs/decisions.md "Memory for settings").
std::vector<MemoryNeed> reference_memory(const Scene& scene, const Settings&, int, int) {
  constexpr double bytes_per_triangle = 200.0;
  double triangles = 0.0;
  for (const Mesh& mesh : scene.meshes) triangles += static_cast<double>(mesh.triangles.size());
  return {{"", "Embree's BVH and two copies of the scene's " + std::to_string(static_cast<long>(triangles)) +
                   " triangles (about 200 bytes each)",
           bytes_per_triangle * triangles}};
}

MethodInfo reference_method() {
  using T = SettingSpec::Type;
  return {"reference", "docs/design.md §1",
          "CPU ground truth: Embree visibility, adaptive quadrature per lit interval",
          {{"rel_tol", T::real, 1e-3, 1e-7, 0.1, {}, "relative accuracy of each pixel's airlight integral"},
           {"min_segments", T::integer, 128, 1, 4096, {},
            "initial panels per ray: shadow features thinner than 1/min_segments of the ray may be missed"}},
          kit::create<ReferenceMethod>(),
          80, reference_memory, {.engine_maps = false, .ground_truth = true}, {}, {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(0, reference_method);

}  // namespace airlight::methods
