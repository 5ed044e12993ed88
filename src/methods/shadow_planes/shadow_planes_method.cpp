#include "methods/kit/gpu_method.hpp"
#include "methods/shadow_planes/crossing_pass.hpp"

#include "gpu/program.hpp"
#include "methods/kit/registry.hpp"

#include <memory>

namespace airlight::methods {
namespace {

// Biri, Arquès & Michelin 2006: the planes' crossings per pixel ("crossings"),
// then per pixel Γ over each light's lit intervals ("airlight",
// resolve.comp.glsl). No shadow map: the shadows are the casters' own edges.
class ShadowPlanes final : public kit::GpuMethod {
public:
  explicit ShadowPlanes(const Settings& s)
      : GpuMethod(s), crossings_(s.real("capacity")), samples_(s.integer("samples")) {}

private:
  void prepare_airlight(const Scene& scene) override { crossings_.prepare(scene); }

  void render_airlight(const kit::SceneFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    {
      gpu::ScopedPass pass(timer, "crossings");
      crossings_.run(frame);
    }
    gpu::ScopedPass pass(timer, "airlight");
    const gpu::Program& program = gpu::cached_compute_program(
        "methods/shadow_planes/resolve.comp.glsl",
        frame.defines() + CrossingPass::defines() + "#define SAMPLES " + std::to_string(samples_) + "\n");
    glUseProgram(program.id());
    crossings_.bind();
    gpu::set_uniform(program, "eye_counts", crossings_.eye_counts());
    glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, crossings_.heads().id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    gpu::dispatch_pixels(frame.width(), frame.height());
  }

  bool uses_shadow_maps() const override { return false; }

  std::vector<std::pair<std::string, double>> stats() const override { return crossings_.stats(); }

  CrossingPass crossings_;
  int samples_;
};

MethodInfo shadow_planes_method() {
  using T = SettingSpec::Type;
  std::vector<SettingSpec> own{
      {"capacity", T::real, 4.0, 0.01, 256.0, {},
       "crossings per pixel (on average over the image) the node pool holds at first; a frame with more grows "
       "the pool and draws the planes again, so no crossing is ever dropped (the report's `redraws`)"},
      {"samples", T::integer, 64, 1, 1024, {},
       "points per lit interval where what Γ has no closed form for — a gobo's colours, the light's leg through "
       "other bounded volumes — is sampled: Γ times the ratio of the exact in-scattering to Γ's integrand there "
       "(even in the angle seen from a spot, uniform along a beam); unused without gobos and volumes"}};
  return {"shadow_planes", "Biri 2006",
          "exact volumetric shadows from the casters' silhouette edges (every triangle edge of an open caster) "
          "extruded away from each light to infinity; per pixel the planes' crossings with the view ray, sorted "
          "and counted from the eye's count, give each light's lit intervals, over which the closed-form Γ is "
          "summed, piece by piece through bounded volumes (Biri §5.2); gobos and the light's leg through other "
          "volumes by a sampled ratio",
          kit::gpu_settings(std::move(own)), [](const Settings& s) { return std::make_unique<ShadowPlanes>(s); }};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(5, shadow_planes_method);

}  // namespace airlight::methods
