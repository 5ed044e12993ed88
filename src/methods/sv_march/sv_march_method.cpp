#include "gpu/program.hpp"
#include "methods/kit/method/gpu_method.hpp"
#include "methods/kit/light_volume/light_volume_mesh.hpp"
#include "methods/kit/counting/lit_interval_pass.hpp"
#include "methods/kit/march/march_pass.hpp"
#include "methods/kit/method/memory_needs.hpp"
#include "methods/kit/method/registry.hpp"

#include <algorithm>
#include <memory>

namespace airlight::methods {
namespace {

constexpr GLuint shell_eye_binding = kit::binding::first_free_storage;
constexpr const char* bounds_vertex = "methods/kit/counting/crossings.vert.glsl";
constexpr const char* bounds_fragment = "methods/sv_march/sv_bounds.frag.glsl";

std::string bounds_defines(const kit::SceneFrame& frame) {
  return frame.defines() + kit::lit_interval_defines() + kit::CountedDraw::defines();
}

// What sv_march.comp.glsl needs besides the march's: the eye counts' binding
// and lit_gamma.glsl's samples.
std::string march_defines(const Settings& s) {
  return "#define BINDING_SHELL_EYE " + std::to_string(shell_eye_binding) + "\n#define SAMPLES " +
         std::to_string(s.integer("samples")) + "\n";
}

// Kingston's shadow-volume march (2018 §4.3, McCool 2000): each light's shadow
// map made a conservative shell mesh on the GPU every frame (between the
// nearest and the farthest depth of each grid cell's texels, kit/
// light_volume_mesh.hpp), its crossings with each pixel's ray reduced to the
// nearest and farthest ([front, back], sv_bounds.frag.glsl), and raymarch's
// march run over [front, back] only, the rest integrated exactly
// (sv_march.comp.glsl). A ray that misses the shell is not marched.
class SvMarch final : public kit::GpuMethod {
public:
  explicit SvMarch(const Settings& s)
      : GpuMethod(s),
        shell_(s.integer("volume_resolution"), kit::LightVolumeMesh::Depth::shell),
        march_(kit::MarchSettings::from(s), "methods/sv_march/sv_march.comp.glsl", march_defines(s)) {}

private:
  void prepare_airlight(const Scene& scene) override {
    shell_.prepare(scene);
    draw_.prepare();
    march_.prepare();
  }

  // The march alone: its link and warm-up take the worker longer than the
  // frame's other passes take this thread, the shell's and the bounds draw's
  // links included (docs/decisions.md "The first frame (issue 28)").
  void link_ahead(const kit::SceneFrame& frame, const gpu::Texture& target) override {
    size_bounds(frame);
    march_.link_ahead(frame, target, [bounds = bounds_.id()] { bind_bounds(bounds); });
  }
  void build_frame(const kit::SceneFrame& frame, gpu::PassTimer& timer) override { shell_.build(frame, timer); }

  void render_airlight(const kit::SceneFrame& frame, const gpu::Texture& target, gpu::PassTimer& timer) override {
    {
      gpu::ScopedPass pass(timer, "bounds");
      draw_bounds(frame);
    }
    gpu::ScopedPass pass(timer, "airlight");
    march_.run(frame, target, [&] {  // what sv_march.comp.glsl reads besides the march's
      bind_bounds(bounds_.id());
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, shell_eye_binding, shell_.eye_count_buffer().id());
    });
  }

  // The warm-up binds the bounds alone: the shells' eye counts, a buffer the
  // build may grow meanwhile, are no part of what llvmpipe compiles for.
  static void bind_bounds(GLuint bounds) { glBindImageTexture(1, bounds, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32UI); }

  // Two layers per light at the G-buffer's size.
  void size_bounds(const kit::SceneFrame& frame) {
    const int layers = std::max(2 * frame.light_count(), 1);  // a texture has a layer; no light reads it
    if (frame.gbuffer_width() == width_ && frame.gbuffer_height() == height_ && layers == layers_) return;
    width_ = frame.gbuffer_width();
    height_ = frame.gbuffer_height();
    layers_ = layers;
    bounds_ = gpu::make_texture(GL_TEXTURE_2D_ARRAY, GL_R32UI, width_, height_, layers_);
  }

  // Per pixel and light, layer 2i: the nearest crossing with its shell (+∞ if
  // none), 2i + 1: the farthest (0 if none).
  void draw_bounds(const kit::SceneFrame& frame) {
    size_bounds(frame);
    const GLuint infinity = 0x7f800000u, zero = 0u;
    for (int layer = 0; layer < layers_; ++layer)
      glClearTexSubImage(bounds_.id(), 0, 0, 0, layer, frame.width(), frame.height(), 1, GL_RED_INTEGER, GL_UNSIGNED_INT,
                         layer % 2 == 0 ? &infinity : &zero);
    const gpu::Program& program =
        gpu::cached_program({{GL_VERTEX_SHADER, bounds_vertex}, {GL_FRAGMENT_SHADER, bounds_fragment}}, bounds_defines(frame));
    glBindImageTexture(0, bounds_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    draw_.draw(frame, program, *shell_.triangles().on_gpu, shell_.triangle_count());
  }

  std::vector<std::pair<std::string, double>> stats() const override {
    std::vector<std::pair<std::string, double>> s = shell_.stats();
    s.insert(s.end(), {{"fragments", draw_.fragments()}, {"light_samples", march_.light_samples()}});
    return s;
  }

  kit::LightVolumeMesh shell_;
  kit::CountedDraw draw_;
  kit::MarchPass march_;
  gpu::Texture bounds_;
  int width_ = 0, height_ = 0, layers_ = 0;
};

// The shells of every light's map, and the bounds' two layers per light past
// the one light its bytes_per_pixel was measured with.
std::vector<MemoryNeed> sv_march_memory(const Scene& scene, const Settings& s, int width, int height) {
  std::vector<MemoryNeed> needs = kit::light_volume_mesh_needs(scene, s, kit::LightVolumeMesh::Depth::shell);
  const double more_lights = static_cast<double>(scene.lights.size()) - 1.0;
  if (more_lights > 0.0)
    needs.push_back({"", "the shell bounds of " + kit::counted(more_lights + 1.0, "light") + " (8 bytes per pixel each)",
                     8.0 * width * height * more_lights, 0.0, 8.0 * width * height * (more_lights + 1.0)});
  return needs;
}

MethodInfo sv_march_method() {
  std::vector<SettingSpec> own = kit::march_settings();
  // A 64² shell: as close as 256² (rRMSE within 10% on the spots) at a
  // quarter of the mesh's and the bounds' cost (docs/decisions.md).
  for (SettingSpec& s : kit::light_volume_settings(64)) own.push_back(std::move(s));
  own.push_back(kit::gamma_samples_setting());
  return {"sv_march", "Kingston 2018 §4.3, McCool 2000",
          "ray marching only where shadows can change: each light's shadow map made a conservative shell mesh "
          "on the GPU every frame, each pixel's ray marched with shadow-map lookups (raymarch's steps, sampling "
          "and jitter) only between its first and last crossing with it, the closed-form Γ before and after",
          kit::per_pixel_settings(std::move(own)), kit::create<SvMarch>(),
          176, kit::gpu_memory(sv_march_memory), {},
          {kit::high_quality_trial({"steps=512", "samples=256", "shadow_resolution=2048"},
            "512 steps per light inside the shells, closed form outside them with 256 samples of its "
            "correction (a light's leg through a dense volume, random scene 13, was 3.8 % off at 64, 0.3 % "
            "at 256; at 512 llvmpipe's loop limit cuts the exact parts short, seed 31: docs/decisions.md), "
            "2048² maps: the sampling within the shells is what is left"), kit::reduced_trial("sv_march")}, {}};
}

}  // namespace

AIRLIGHT_REGISTER_METHOD(10, sv_march_method);

}  // namespace airlight::methods
