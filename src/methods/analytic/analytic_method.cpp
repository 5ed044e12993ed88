#include "methods/kit/method/gpu_method.hpp"
#include "gpu/program.hpp"
#include "optics/gamma.hpp"

#include "methods/kit/method/registry.hpp"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace airlight::methods {
namespace {

constexpr GLuint sun_table_unit = kit::binding::first_free_texture;  // BINDING_SUN_TABLE
constexpr const char* program = "methods/analytic/analytic.comp.glsl";

std::vector<SettingSpec> analytic_settings() {
  using T = SettingSpec::Type;
  return {{"F", T::choice, 1, 0, 0, {"table", "shader"},
           "how Sun et al.'s F(u, v) = ∫_0^v exp(−u tan ξ) dξ is evaluated where Γ uses it (isotropic medium, "
           "physical light model, point lights and hard-edged spots; Kingston §5.2.1): table = bilinear in a "
           "precomputed R32F texture (optics::SunTable, Kingston's choice), shader (the default: the more "
           "accurate and, on the seed scenes, the faster) = Gauss–Legendre in the shader. Other phase functions, smooth cone edges and the simplified model are integrated in the "
           "angle either way"}};
}

// One dispatch over the pixels: every pixel sums Γ of every light to its
// G-buffer distance (analytic.comp.glsl).
class Analytic final : public kit::GpuMethod {
public:
  enum class F { table, shader };  // the `F` setting's choices, in order
  explicit Analytic(const Settings& s) : GpuMethod(s), table_(s.option<F>("F") == F::table) {}

private:
  void prepare_airlight(const Scene&) override {
    if (table_) upload_table();
  }

  // Sun et al.'s F(u, v) as an R32F texture (Kingston 4.2.3); it depends on no
  // scene, so it is computed once per process. One level, nearest: the shader
  // filters bilinearly from texelFetch reads (optics::SunTable), so no
  // derivative picks a mip level or filter at a depth edge.
  void upload_table() {
    static const optics::SunTable table = optics::build_sun_table();
    table_texture_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32F, table.width, table.height);
    glTextureSubImage2D(table_texture_.id(), 0, 0, 0, table.width, table.height, GL_RED, GL_FLOAT,
                        table.texels.data());
  }

  std::string defines(const kit::SceneFrame& frame) const {
    return frame.defines() + "#define BINDING_SUN_TABLE " + std::to_string(sun_table_unit) + "\n" +
           (table_ ? "#define SUN_F_TABLE\n" : "");
  }

  // Warmed on the worker beside the frame's passes, then run there (GpuMethod::link_ahead).
  void link_ahead(const kit::SceneFrame& frame, const gpu::Texture& target) override {
    gpu::link_compute_ahead(program, defines(frame), frame.warm_pixels(inputs(target)));
  }

  void render_airlight(const kit::SceneFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    gpu::ScopedPass pass(timer, "airlight");
    const gpu::Program& p = gpu::cached_compute_program(program, defines(frame));
    frame.run_where_warmed(p, [&] {
      inputs(target)();
      glUseProgram(p.id());
      frame.dispatch_pixels();
    });
    closed_forms_ = static_cast<double>(frame.width()) * frame.height() * frame.light_count();
  }

  // Binds the table and the target, by their names (SceneFrame::warm_pixels).
  std::function<void()> inputs(const gpu::Texture& target) const {
    return [table = table_ ? table_texture_.id() : 0, target = target.id()] {
      if (table) glBindTextureUnit(sun_table_unit, table);
      glBindImageTexture(0, target, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    };
  }

  bool uses_shadow_maps() const override { return false; }  // Γ is unoccluded

  std::vector<std::pair<std::string, double>> stats() const override { return {{"closed_forms", closed_forms_}}; }

  bool table_;
  gpu::Texture table_texture_;
  double closed_forms_ = 0.0;
};

MethodInfo analytic_method() {
  return {"analytic", "Sun et al. 2005 via Kingston 4.2",
          "per pixel, the closed-form unoccluded airlight of every light from the eye to the G-buffer distance "
          "(Sun et al. 2005, Kingston eqs. 36-40; other phase functions in the angle, the simplified model by "
          "Nilsson eq. 2.17), with F(u, v) from a table or integrated in the shader; no volumetric shadows "
          "(occluders only end the view ray), and the medium that fills space only: bounded volumes and gobo "
          "colours are ignored",
          kit::per_pixel_settings(analytic_settings()), kit::create<Analytic>(),
          128, kit::gpu_memory(), {.volumetric_shadows = false, .bounded_volumes = false, .gobos = false},
          {{"exact", {}, Trial::Measure::worst_pixel, 0.02,
            "Sun et al.'s closed form against the reference without shadows, volumes or gobos: the same integral, evaluated in float "
            "(its F by the shader's series), so any pixel 2 % off is a defect"}, kit::reduced_trial("analytic")}, {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(4, analytic_method);

}  // namespace airlight::methods
