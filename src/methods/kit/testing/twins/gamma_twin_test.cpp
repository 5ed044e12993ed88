// methods/kit/gamma/closed_form.glsl (closed_form_airlight, both variants) against
// optics::gamma (src/optics/gamma.cpp, itself tested against quadrature) on
// random view segments of three scenes: an HG medium (Biri's angular path:
// point, hard and smooth-edged spots, a beam, an unbounded sun), an isotropic
// one (the Sun path) and the simplified light model (Nilsson); and
// component_airlight for the components of pieces inside two box volumes.
#include "methods/kit/frame/scene_frame.hpp"
#include "gpu/gl.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/testing/twins/twin_test_support.hpp"
#include "optics/gamma.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace airlight::kit {
namespace {

using namespace twin;

Scene gamma_scene(const Phase& phase, LightModelType model) {
  Scene s;
  s.medium.sigma_s = {0.05f, 0.2f, 0.5f};
  s.medium.sigma_a = {0.01f, 0.05f, 0.5f};
  s.medium.phase = phase;
  s.light_model = {model, 0.5f, 1.0f};
  Light point;
  point.position = {0.5f, 2.2f, 0.8f};
  point.intensity = {30.0f, 20.0f, 10.0f};
  Light spot;
  spot.type = LightType::spot;
  spot.position = {-1.0f, 4.0f, 1.5f};
  spot.direction = glm::normalize(glm::vec3(1.3f, -4.0f, -2.0f));
  spot.intensity = {60.0f, 50.0f, 40.0f};
  spot.cone_deg = 35.0f;
  Light soft = spot;
  soft.position = {1.0f, 3.0f, -1.0f};
  soft.direction = glm::normalize(glm::vec3(-1.0f, -2.0f, 0.5f));
  soft.cone_deg = 120.0f;  // wider than a half-space: up to two pieces per ray
  soft.edge_deg = 20.0f;
  Light beam;
  beam.type = LightType::directional;
  beam.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  beam.irradiance = {2.0f, 1.5f, 1.0f};
  beam.gobo_up = {0, 0, 1};
  beam.beam = Beam{{0.2f, 4.0f, -0.3f}, {3.0f, 2.0f}, 6.0f};
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, -0.5f));
  sun.irradiance = glm::vec3(0.5f);
  s.lights = {point, spot, soft, beam, sun};
  s.meshes.push_back(floor_mesh());  // SceneFrame draws something
  return s;
}

// The table variant's texture: SunTable's texels as R32F, nearest (the shader filters).
constexpr GLuint sun_table_unit = binding::first_free_texture;
Texture upload_sun_table(const optics::SunTable& table) {
  Texture t = make_texture(GL_TEXTURE_2D, GL_R32F, table.width, table.height);
  glTextureSubImage2D(t.id(), 0, 0, 0, table.width, table.height, GL_RED, GL_FLOAT, table.texels.data());
  glBindTextureUnit(sun_table_unit, t.id());
  return t;
}

// What a case asks Γ for: the medium optics::gamma sees and the GLSL
// component's phase (-1: the medium that fills space, v: volume v).
struct Component {
  Medium medium;
  int phase = -1;
};
using DrawComponent = std::function<Component(std::mt19937&)>;

// A piece of the ray inside volume 0, volume 1 or both, and one of the media
// filling it (Biri §5.2): its σs and phase, and σt_piece, the sum of all their
// σt, on both legs (σa = σt_piece − σs).
Component draw_component(const Scene& scene, std::mt19937& rng) {
  const int inside = std::uniform_int_distribution<int>(1, 3)(rng);  // bit v: the piece is in volume v
  glm::vec3 sigma_t = scene.medium.sigma_t();
  std::vector<Component> filling = {{scene.medium, -1}};
  for (int v = 0; v < 2; ++v) {
    if (!(inside >> v & 1)) continue;
    const Volume& volume = scene.volumes[size_t(v)];
    sigma_t += volume.sigma_t();
    filling.push_back({Medium{volume.sigma_s, {}, volume.phase}, v});
  }
  Component m = filling[std::uniform_int_distribution<size_t>(0, filling.size() - 1)(rng)];
  m.medium.sigma_a = sigma_t - m.medium.sigma_s;
  return m;
}

// Runs both variants over random segments of `scene` and checks them against
// optics::gamma: `tolerance` relative to the largest channel of the C++ value.
// Without `draw`, closed_form_airlight (the filling medium); with it,
// component_airlight of the component it draws per case.
void check_scene(const std::string& name, const Scene& scene, double tolerance, double table_tolerance,
                 const DrawComponent& draw = {}) {
  Context::headless();
  SceneFrame frame;
  frame.prepare(scene);
  PassTimer timer;
  frame.render(frame_inputs(scene, 8, 8), {}, nullptr, {}, timer);
  frame.bind();
  const Texture table = upload_sun_table(optics::build_sun_table());
  std::mt19937 rng(11);
  std::vector<glm::vec4> in;
  std::vector<Component> components;
  const int n = 4000, stride = 5;  // gamma.comp.glsl's IN_STRIDE
  for (int k = 0; k < n; ++k) {
    const glm::vec3 eye(uniform(rng, -3, 3), uniform(rng, -1, 5), uniform(rng, -3, 3));
    const float t0 = uniform(rng, 0, 1) < 0.3f ? uniform(rng, 0, 3) : 0.0f;
    const glm::vec3 dir = random_unit(rng);
    const float t1 = t0 + uniform(rng, 0, 12);
    const Component& m = components.emplace_back(draw ? draw(rng) : Component{scene.medium, -1});
    in.insert(in.end(), {glm::vec4(eye, float(k % scene.lights.size())), glm::vec4(dir, float(m.phase)),
                         glm::vec4(t0, t1, 0, 0), glm::vec4(m.medium.sigma_s, 0), glm::vec4(m.medium.sigma_t(), 0)});
  }
  const std::string defines =
      frame.defines() + "#define TWIN_BINDING 8\n" + (draw ? "#define COMPONENT_TWIN\n" : "");
  const std::string table_defines =
      defines + "#define SUN_F_TABLE\n#define BINDING_SUN_TABLE " + std::to_string(sun_table_unit) + "\n";
  const auto shader_out = run_twin("gamma.comp.glsl", in, stride, 1, defines, 8);
  const auto table_out = run_twin("gamma.comp.glsl", in, stride, 1, table_defines, 8);
  Errors in_shader(name + " in-shader"), tabled(name + " table"), variants(name + " table vs in-shader");
  for (int k = 0; k < n; ++k) {
    const glm::vec4* args = &in[size_t(stride * k)];
    const Light& light = scene.lights[size_t(args[0].w)];
    const optics::Ray ray{glm::dvec3(args[0]), glm::dvec3(args[1])};
    const glm::dvec3 g =
        optics::gamma(components[size_t(k)].medium, scene.light_model, light, ray, args[2].x, args[2].y);
    const double scale = std::max({g.x, g.y, g.z});
    auto where = [&] {
      return "case " + std::to_string(k) + " light " + std::to_string(int(args[0].w)) + " component " +
             std::to_string(components[size_t(k)].phase);
    };
    for (int c = 0; c < 3; ++c) {
      in_shader.check(shader_out[k][c], g[c], tolerance * scale + 1e-30, where);
      tabled.check(table_out[k][c], g[c], table_tolerance * scale + 1e-30, where);
      variants.check(table_out[k][c], shader_out[k][c], table_tolerance * scale + 1e-30, where);
    }
  }
}

Phase hg_murky() {
  Phase hg;
  hg.lobes = {PhaseLobe{PhaseType::henyey_greenstein, 0.6f, 0.7f}, PhaseLobe{PhaseType::murky, 0.0f, 0.3f}};
  return hg;
}

// gamma_scene with two overlapping box volumes: an isotropic one (its
// component takes the Sun path) and a backward Henyey–Greenstein one (Biri's
// angular path with a volume's lobe).
Scene bounded_scene(LightModelType model) {
  Scene s = gamma_scene(hg_murky(), model);
  Volume isotropic;
  isotropic.min = {-2.0f, 0.0f, -2.0f};
  isotropic.max = {0.5f, 3.0f, 1.0f};
  isotropic.sigma_s = {0.3f, 0.2f, 0.1f};
  isotropic.sigma_a = {0.05f, 0.1f, 0.2f};
  Volume backward;
  backward.min = {-1.0f, -1.0f, -1.0f};
  backward.max = {2.0f, 2.0f, 2.0f};
  backward.sigma_s = {0.1f, 0.3f, 0.2f};
  backward.sigma_a = {0.02f, 0.02f, 0.3f};
  backward.phase.lobes = {PhaseLobe{PhaseType::henyey_greenstein, -0.4f, 1.0f}};
  s.volumes = {isotropic, backward};
  return s;
}

// Every σ replaced by its green channel: GREY_MEDIA, closed_form.glsl's one-channel paths.
Scene grey(Scene s) {
  auto grey_of = [](Color& c) { c = Color(c.g); };
  grey_of(s.medium.sigma_s);
  grey_of(s.medium.sigma_a);
  for (Volume& v : s.volumes) {
    grey_of(v.sigma_s);
    grey_of(v.sigma_a);
  }
  return s;
}

void check_components(const std::string& name, const Scene& scene, double tolerance, double table_tolerance) {
  check_scene(name, scene, tolerance, table_tolerance,
              [&scene](std::mt19937& rng) { return draw_component(scene, rng); });
}

// Tolerances, relative to the largest channel: float geometry and exp (the Sun
// twin's 2e-4, OpticsTwin.SunFunctionAndAirlight), Biri's sums of panels × 8
// nodes in float, cone and beam ends in float (~1e-6 m on segments of
// metres): 1e-3. The table variant differs only on the isotropic Sun path, by
// at most the SunTable path's bound (gamma_test.cpp: 0.5%): 5e-3. The
// components of bounded media take the same paths with other σs, σt and
// lobes, so the same bounds hold (5e-3 for the table: the isotropic volume's
// component takes the Sun path).
TEST(GammaTwin, BiriPhaseFunctions) {
  check_scene("Γ HG+murky", gamma_scene(hg_murky(), LightModelType::physical), 1e-3, 1e-3);
}

TEST(GammaTwin, SunIsotropicBothVariants) {
  check_scene("Γ isotropic", gamma_scene(Phase{}, LightModelType::physical), 1e-3, 5e-3);
}

TEST(GammaTwin, NilssonSimplified) {
  check_scene("Γ simplified", gamma_scene(Phase{}, LightModelType::simplified), 1e-3, 1e-3);
}

// A hard-edged spot wider than a half-space: a line may cross the dark backward
// cone between two lit pieces, each its own closed form (closed_form.glsl
// hard_spot_gamma), in the Sun path and Biri's.
TEST(GammaTwin, WideHardSpotInBothPaths) {
  for (const Phase& phase : {Phase{}, hg_murky()}) {
    Scene s = gamma_scene(phase, LightModelType::physical);
    Light wide = s.lights[2];
    wide.edge_deg = 0.0f;
    s.lights = {wide};
    check_scene("Γ wide hard spot", s, 1e-3, 5e-3);
  }
}

TEST(GammaTwin, ComponentsOfBoundedMedia) {
  check_components("Γ components", bounded_scene(LightModelType::physical), 1e-3, 5e-3);
}

TEST(GammaTwin, ComponentsOfGreyBoundedMedia) {
  check_components("Γ grey components", grey(bounded_scene(LightModelType::physical)), 1e-3, 5e-3);
}

TEST(GammaTwin, ComponentsNilssonSimplified) {
  check_components("Γ simplified comp.", bounded_scene(LightModelType::simplified), 1e-3, 1e-3);
}

}  // namespace
}  // namespace airlight::kit
