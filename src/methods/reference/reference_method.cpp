#include "methods/kit/registry.hpp"
#include "reference/reference.hpp"

namespace airlight::methods {

namespace {

class ReferenceMethod final : public Method {
public:
  explicit ReferenceMethod(const Settings& s)
      : settings_{s.real("rel_tol"), s.integer("min_segments")} {}

  void prepare(const Scene& scene) override { scene_ = &scene; }

  Frame render(int width, int height) override {
    reference::Frame r = reference::render(*scene_, width, height, settings_);
    Frame frame;
    frame.airlight = std::move(r.airlight);
    frame.surface = std::move(r.surface);
    frame.stats = {{"shadow_rays", static_cast<double>(r.shadow_rays)}};
    return frame;
  }

private:
  reference::Settings settings_;
  const Scene* scene_ = nullptr;
};

MethodInfo reference_method() {
  using T = SettingSpec::Type;
  return {"reference", "DESIGN §1",
          "CPU ground truth: Embree visibility, adaptive quadrature per lit interval",
          {{"rel_tol", T::real, 1e-3, 1e-7, 0.1, {}, "relative accuracy of each pixel's airlight integral"},
           {"min_segments", T::integer, 32, 1, 4096, {},
            "initial panels per ray: shadow features thinner than 1/min_segments of the ray may be missed"}},
          [](const Settings& s) { return std::make_unique<ReferenceMethod>(s); }};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(0, reference_method);

}  // namespace airlight::methods
