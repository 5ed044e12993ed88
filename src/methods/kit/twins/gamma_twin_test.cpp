// methods/kit/closed_form.glsl (closed_form_airlight, both variants) against
// optics::gamma (src/optics/gamma.cpp, itself tested against quadrature) on
// random view segments of three scenes: an HG medium (Biri's angular path:
// point, hard and smooth-edged spots, a beam, an unbounded sun), an isotropic
// one (the Sun path) and the simplified light model (Nilsson).
#include "methods/kit/scene_frame.hpp"
#include "gpu/gl.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/twins/twin_test_support.hpp"
#include "optics/gamma.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
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

// Runs both variants over random segments of `scene` and checks them against
// optics::gamma: `tolerance` relative to the largest channel of the C++ value.
void check_scene(const std::string& name, const Scene& scene, double tolerance, double table_tolerance) {
  Context::headless();
  SceneFrame frame;
  frame.prepare(scene);
  PassTimer timer;
  frame.render(frame_inputs(scene, 8, 8), {}, nullptr, {}, timer);
  frame.bind();
  const Texture table = upload_sun_table(optics::build_sun_table());
  std::mt19937 rng(11);
  std::vector<glm::vec4> in;
  const int n = 4000;
  for (int k = 0; k < n; ++k) {
    const glm::vec3 eye(uniform(rng, -3, 3), uniform(rng, -1, 5), uniform(rng, -3, 3));
    const float t0 = uniform(rng, 0, 1) < 0.3f ? uniform(rng, 0, 3) : 0.0f;
    in.insert(in.end(), {glm::vec4(eye, float(k % scene.lights.size())), glm::vec4(random_unit(rng), 0.0f),
                         glm::vec4(t0, t0 + uniform(rng, 0, 12), 0, 0)});
  }
  const std::string defines = frame.defines() + "#define TWIN_BINDING 8\n";
  const std::string table_defines =
      defines + "#define SUN_F_TABLE\n#define BINDING_SUN_TABLE " + std::to_string(sun_table_unit) + "\n";
  const auto shader_out = run_twin("gamma.comp.glsl", in, 3, 1, defines, 8);
  const auto table_out = run_twin("gamma.comp.glsl", in, 3, 1, table_defines, 8);
  Errors in_shader(name + " in-shader"), tabled(name + " table"), variants(name + " table vs in-shader");
  for (int k = 0; k < n; ++k) {
    const Light& light = scene.lights[size_t(in[3 * k].w)];
    const optics::Ray ray{glm::dvec3(in[3 * k]), glm::dvec3(in[3 * k + 1])};
    const glm::dvec3 g = optics::gamma(scene.medium, scene.light_model, light, ray, in[3 * k + 2].x, in[3 * k + 2].y);
    const double scale = std::max({g.x, g.y, g.z});
    auto where = [&] { return "case " + std::to_string(k) + " light " + std::to_string(int(in[3 * k].w)); };
    for (int c = 0; c < 3; ++c) {
      in_shader.check(shader_out[k][c], g[c], tolerance * scale + 1e-30, where);
      tabled.check(table_out[k][c], g[c], table_tolerance * scale + 1e-30, where);
      variants.check(table_out[k][c], shader_out[k][c], table_tolerance * scale + 1e-30, where);
    }
  }
}

// Tolerances, relative to the largest channel: float geometry and exp (the Sun
// twin's 2e-4, OpticsTwin.SunFunctionAndAirlight), Biri's sums of panels × 8
// nodes in float, cone and beam ends in float (~1e-6 m on segments of
// metres): 1e-3. The table variant differs only on the isotropic Sun path, by
// at most the SunTable path's bound (gamma_test.cpp: 0.5%): 5e-3.
TEST(GammaTwin, BiriPhaseFunctions) {
  Phase hg;
  hg.lobes = {PhaseLobe{PhaseType::henyey_greenstein, 0.6f, 0.7f}, PhaseLobe{PhaseType::murky, 0.0f, 0.3f}};
  check_scene("Γ HG+murky", gamma_scene(hg, LightModelType::physical), 1e-3, 1e-3);
}

TEST(GammaTwin, SunIsotropicBothVariants) {
  check_scene("Γ isotropic", gamma_scene(Phase{}, LightModelType::physical), 1e-3, 5e-3);
}

TEST(GammaTwin, NilssonSimplified) {
  check_scene("Γ simplified", gamma_scene(Phase{}, LightModelType::simplified), 1e-3, 1e-3);
}

}  // namespace
}  // namespace airlight::kit
