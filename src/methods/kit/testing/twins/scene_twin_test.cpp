// The scene-level GLSL of src/methods/kit/frame/scene.glsl (light_map, the arrival
// with and without it, the light leg's depth, inscatter) against the C++
// optics on a scene with every kind of light, through the shared frame.
#include "methods/kit/frame/scene_frame.hpp"
#include "methods/kit/frame/scene_defines.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/testing/twins/twin_test_support.hpp"
#include "optics/airlight.hpp"
#include "optics/light.hpp"
#include "optics/media.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace airlight::kit {
namespace {

using namespace twin;

// The lights of the scene.glsl twin: two beams (one with a gobo), a spot with
// a gobo and a smooth edge, a point light and an unbounded sun, in an HG
// medium with a Rayleigh box volume that the beams' legs cross.
Scene light_twin_scene() {
  Scene s;
  s.medium.sigma_s = {0.05f, 0.04f, 0.03f};
  s.medium.sigma_a = glm::vec3(0.01f);
  s.medium.phase.lobes = {PhaseLobe{PhaseType::henyey_greenstein, 0.3f, 1.0f}};
  Volume box;
  box.min = {-1, 0, -1};
  box.max = {1, 2, 1};
  box.sigma_s = {0.2f, 0.1f, 0.3f};
  box.sigma_a = glm::vec3(0.05f);
  box.phase.lobes = {PhaseLobe{PhaseType::rayleigh, 0.0f, 1.0f}};
  s.volumes.push_back(box);
  auto gobo = std::make_shared<Image>(8, 6);  // texels all differ: any flip of u, v shows
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) gobo->at(x, y) = Color(0.1f + 0.9f * x / 7.0f, 0.1f + 0.9f * y / 5.0f, (x + y) % 2 ? 1.0f : 0.2f);
  Light beam;
  beam.type = LightType::directional;
  beam.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  beam.irradiance = {2.0f, 1.5f, 1.0f};
  beam.gobo_up = {0, 0, 1};
  beam.beam = Beam{{0.2f, 4.0f, -0.3f}, {3.0f, 2.0f}, 6.0f};
  beam.gobo = gobo;
  Light plain_beam = beam;
  plain_beam.direction = {0, -1, 0};
  plain_beam.beam = Beam{{1.0f, 3.0f, 1.0f}, {1.5f, 2.5f}, 4.0f};
  plain_beam.gobo = nullptr;
  Light spot;
  spot.type = LightType::spot;
  spot.position = {-1.0f, 4.0f, 1.5f};
  spot.direction = glm::normalize(glm::vec3(1.3f, -4.0f, -2.0f));
  spot.intensity = {60.0f, 50.0f, 40.0f};
  spot.cone_deg = 35.0f;
  spot.edge_deg = 8.0f;
  spot.gobo_up = {0, 0, -1};
  spot.gobo = gobo;
  Light point;
  point.position = {0.5f, 2.2f, 0.8f};
  point.intensity = glm::vec3(30.0f);
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(-0.2f, -1.0f, -0.5f));
  sun.irradiance = glm::vec3(0.5f);
  s.lights = {beam, plain_beam, spot, point, sun};
  s.meshes.push_back(floor_mesh());  // something to draw into the shadow maps
  return s;
}

// The light without its light map: a spot as a point light, a beam as an
// unbounded directional light (optics has no "unmapped" arrival; this is it).
Light unmapped(Light light) {
  if (light.type == LightType::spot) light.type = LightType::point;
  light.beam.reset();
  return light;
}

// How far x is from where the light map or the scattering jumps: the beams'
// faces and the volume's faces (the spot's smooth edge is continuous), in metres.
double distance_to_jumps(const Scene& scene, const glm::dvec3& x) {
  double d = std::numeric_limits<double>::infinity();
  for (const Light& light : scene.lights) {
    if (!optics::has_beam(light)) continue;
    const glm::dvec2 uv = optics::beam_uv(light, x);
    const double s = optics::beam_depth(light, x);
    d = std::min({d, std::abs(uv.x) * light.beam->size.x, std::abs(1 - uv.x) * light.beam->size.x,
                  std::abs(uv.y) * light.beam->size.y, std::abs(1 - uv.y) * light.beam->size.y, std::abs(s),
                  std::abs(s - light.beam->length)});
  }
  for (const Volume& v : scene.volumes)
    for (int k = 0; k < 3; ++k) d = std::min({d, std::abs(x[k] - v.min[k]), std::abs(x[k] - v.max[k])});
  return d;
}

// light_map, light_arrival (and unmapped), light_leg_depth, inscatter (and
// unmapped) of scene.glsl, reading the lights as kit::SceneFrame uploads
// them, against optics at random points: around the beams (half the points)
// and anywhere in the scene, seen from random eyes.
TEST(SceneTwin, LightMapArrivalLegAndInscatter) {
  Context& context = Context::headless();
  const Scene scene = light_twin_scene();
  SceneFrame frame;
  frame.prepare(scene);
  PassTimer timer;
  frame.render(frame_inputs(scene, 8, 8), {}, nullptr, {}, timer);  // fills the frame block the twin reads
  frame.bind();
  std::mt19937 rng(7);
  auto anywhere = [&] { return glm::vec3(uniform(rng, -3, 3), uniform(rng, -1, 5), uniform(rng, -3, 3)); };
  std::vector<glm::vec4> in;
  for (int k = 0; k < 4000; ++k) {
    const int l = k % int(scene.lights.size());
    glm::vec3 x = anywhere();
    if (k % 2 && optics::has_beam(scene.lights[l])) {  // around the beam's box
      const Light& light = scene.lights[l];
      glm::dvec3 right, up;
      optics::gobo_frame(light, right, up);
      const Beam& b = *light.beam;
      x = glm::vec3(glm::dvec3(b.origin) + double(uniform(rng, -0.6f, 0.6f) * b.size.x) * right +
                    double(uniform(rng, -0.6f, 0.6f) * b.size.y) * up +
                    double(uniform(rng, -0.1f, 1.1f) * b.length) * glm::normalize(glm::dvec3(light.direction)));
    }
    in.emplace_back(x, float(l));
    in.emplace_back(anywhere(), 0.0f);
  }
  const auto out = run_twin("scene_light.comp.glsl", in, 2, 7, frame.defines() + "#define TWIN_BINDING 8\n",
                            binding::first_free_storage);
  context.check("scene twin");

  Errors maps("light_map", false), irradiance("light_arrival"), to_light("to_light", false),
      plain("arrival_unmapped"), legs("light_leg_depth", false), inscatter("inscatter"),
      inscatter_plain("inscatter_unmapped");
  int near_jumps = 0, lit_in_beams = 0;
  for (size_t i = 0; i < in.size() / 2; ++i) {
    const Light& light = scene.lights[size_t(in[2 * i].w)];
    const glm::dvec3 x(in[2 * i]), eye(in[2 * i + 1]);
    const glm::vec4* o = &out[7 * i];
    auto where = [&] {
      return "light " + std::to_string(int(in[2 * i].w)) + " x " + str(in[2 * i]) + " eye " + str(in[2 * i + 1]);
    };
    const glm::dvec3 map = optics::light_map(light, x);
    const optics::Arrival a = optics::arrival(light, scene.light_model, x);
    const glm::dvec3 unmapped_e = optics::arrival(unmapped(light), scene.light_model, x).irradiance;
    const glm::dvec3 leg = optics::light_leg_depth(scene, light, x);
    const optics::Ray ray{eye, glm::normalize(x - eye)};
    const double t = glm::length(x - eye);
    const glm::dvec3 e = optics::inscatter(scene, light, ray, t);
    const glm::dvec3 e_plain = optics::scattering(scene, x, glm::dot(a.to_light, ray.dir)) * unmapped_e *
                               glm::exp(-(leg + optics::eye_leg_depth(scene, eye, x)));
    // Within 1e-5 m of a beam's or the volume's face (float positions are good
    // to ~1e-6 m here) the two sides may see different sides of the jump.
    const bool jump = distance_to_jumps(scene, x) < 1e-5;
    near_jumps += jump;
    lit_in_beams += optics::has_beam(light) && map != glm::dvec3(0.0);
    for (int c = 0; c < 3; ++c) {
      plain.check(o[3][c], unmapped_e[c], 1e-6 * unmapped_e[c], where);  // float falloff
      // Chords and lengths in float: ~4e-6 m (media twin) times σt <= 0.4.
      legs.check(o[4][c], leg[c], 4e-6, where);
      if (jump) {
        maps.finite(o[0][c], where);
        irradiance.finite(o[1][c], where);
        inscatter.finite(o[5][c], where);
        inscatter_plain.finite(o[6][c], where);
        continue;
      }
      // Gobo colour: bilinear in float (1e-6 of texels <= 1) at uv off by
      // ~1e-6 (float positions and frame, as BeamCoordinatesAndInside),
      // times the texel slope (<= 0.9 per texel, 8 texels per unit u): 2e-5.
      maps.check(o[0][c], map[c], 2e-5, where);
      // The map's error relative to its value, plus float falloff (1e-6).
      irradiance.check(o[1][c], a.irradiance[c], 2e-5 * glm::length(unmapped_e) + 1e-6 * a.irradiance[c], where);
      // The product of the above and a phase function (1e-5, phase twin), exp
      // of depths good to ~1e-5: 1e-4 relative, and the map's 2e-5 absolute.
      inscatter_plain.check(o[6][c], e_plain[c], 1e-4 * e_plain[c], where);
      inscatter.check(o[5][c], e[c], 1e-4 * e[c] + 2e-5 * e_plain[c], where);
    }
    to_light.check(glm::distance(glm::dvec3(o[2]), a.to_light), 0.0, 1e-6, where);  // unit vectors in float
    if (light.type == LightType::directional)
      EXPECT_EQ(o[1].w, -1.0f) << where() << ": a directional light is infinitely far";
    else
      irradiance.check(o[1].w, a.distance, 1e-6 * a.distance, where);
  }
  std::printf("scene twin: %d of %zu points within 1e-5 m of a jump, compared for finiteness only\n", near_jumps,
              in.size() / 2);
  EXPECT_GT(lit_in_beams, 500);  // the beams' insides are sampled (half of their 1600 points are near them)
}

// FOR_EACH_LIGHT_SHARED on the stage's five spots of two structures (three
// plain with soft edges, two with gobos): one copy of the code per structure,
// run for each light once, reading that light's data in its structure's
// slot; after the loops every light's slot holds its own data again.
TEST(SceneTwin, SharedLightLoopsVisitEachLightOnceWithItsData) {
  Context& context = Context::headless();
  const Scene scene = builtin_scene("stage");
  SceneFrame frame;
  frame.prepare(scene);
  PassTimer timer;
  frame.render(frame_inputs(scene, 8, 8), {}, nullptr, {}, timer);
  frame.bind();
  const std::string& defines = frame.defines();
  const size_t loops = defines.find("#define FOR_EACH_LIGHT_SHARED(F)");
  ASSERT_NE(loops, std::string::npos);
  const std::string line = defines.substr(loops, defines.find('\n', loops) - loops);
  int copies = 0;
  for (size_t at = line.find(" F("); at != std::string::npos; at = line.find(" F(", at + 1)) ++copies;
  EXPECT_EQ(copies, 2) << line;

  const int n = static_cast<int>(scene.lights.size());
  const auto out = run_twin("shared_lights.comp.glsl", {glm::vec4(0.0f)}, 1, 2 * n,
                            defines + "#define TWIN_BINDING 8\n", binding::first_free_storage);
  context.check("shared light loops");
  std::vector<int> visits(n, 0);
  for (int k = 0; k < 2 * n; ++k) {
    const int code = static_cast<int>(out[k].w), slot = code % 64, light = code / 64;
    ASSERT_TRUE(light >= 0 && light < n) << k;
    EXPECT_EQ(glm::vec3(out[k]), scene.lights[light].position) << "output " << k << ": light " << light;
    if (k < n) {
      ++visits[light];
      EXPECT_EQ(slot, frame.representative(light)) << "visit " << k << ": light " << light;
    } else {
      EXPECT_EQ(slot, k - n);
      EXPECT_EQ(light, k - n) << "light " << slot << "'s slot after the loops";
    }
  }
  EXPECT_EQ(visits, std::vector<int>(n, 1));
}

}  // namespace
}  // namespace airlight::kit
