// The GLSL optics twins (shaders/optics/*.glsl) against the C++ optics they
// mirror (src/optics/, itself tested against quadrature): each twin runs in a
// compute shader (src/methods/kit/testing/twins/shaders/) on thousands of inputs, and every
// output must be finite and within the tolerance stated beside its check.
#include "methods/kit/testing/twins/twin_test_support.hpp"
#include "gpu/context.hpp"
#include "methods/kit/frame/scene_frame.hpp"
#include "gpu/program.hpp"
#include "optics/airlight.hpp"
#include "optics/closed_form.hpp"
#include "optics/light.hpp"
#include "optics/media.hpp"
#include "optics/phase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace airlight::kit {
namespace {

using namespace twin;

// Points on a 1/8 grid (exact in float, so "on the face" and "axis parallel"
// mean the same to both sides).
glm::vec3 grid_point(std::mt19937& rng) {
  std::uniform_int_distribution<int> n(-24, 24);
  return glm::vec3(n(rng), n(rng), n(rng)) / 8.0f;
}

// ---------------------------------------------------------------- phase.glsl

TEST(OpticsTwin, PhaseLobesOverTheWholeSphere) {
  std::vector<float> gs{-0.95f, -0.94f, -0.938f, -0.9f, -0.7f, -0.5f, -0.3f, -0.1f, 0.0f,
                        0.1f,   0.3f,   0.5f,    0.7f,  0.9f,  0.938f, 0.94f, 0.95f};
  std::vector<float> cosines;
  for (int i = 0; i <= 400; ++i) cosines.push_back(-1.0f + i / 200.0f);
  for (int k = 4; k <= 24; k += 2) {  // the peaks at cos θ = ±1, where HG and Schlick are steepest
    cosines.push_back(1.0f - std::ldexp(1.0f, -k));
    cosines.push_back(-1.0f + std::ldexp(1.0f, -k));
  }
  std::vector<glm::vec4> in;
  for (int type = 0; type <= static_cast<int>(PhaseType::murky); ++type)
    for (float g : gs)
      for (float c : cosines) in.emplace_back(float(type), g, c, 0.0f);
  const auto out = run_twin("phase.comp.glsl", in, 1, 1);

  Errors lobes("phase_lobe"), schlick("phase_lobe schlick"), k_errors("schlick_k");
  for (size_t i = 0; i < in.size(); ++i) {
    const PhaseLobe lobe{static_cast<PhaseType>(int(in[i].x)), in[i].y, 1.0f};
    const double c = in[i].z;
    const double cpu = optics::phase(lobe, c);
    auto where = [&] { return "type " + std::to_string(int(in[i].x)) + " g " + std::to_string(lobe.g) +
                              " cos " + std::to_string(c); };
    if (lobe.type == PhaseType::schlick) {
      // Kingston eq. 16 cancels in 1 - k near the clamp (|k| → 0.999): k's float
      // rounding (~2ε) is amplified by 1/(1 - |k|) in (1 + k)/(1 - k)-like
      // terms, and the float clamp 0.999f differs from 0.999 by 1.3e-8.
      const double k = optics::schlick_k(lobe.g);
      schlick.check(out[i].x, cpu, cpu * (1e-5 + 8 * 6e-8 / (1.0 - std::abs(k))), where);
    } else {
      // Smooth in float: a handful of roundings, sqrt and division to ≤ 3 ulp;
      // HG's denominator is written without cancellation, and the hazy/murky
      // powers by squaring (≤ 32·ε/2): 1e-5 relative.
      lobes.check(out[i].x, cpu, cpu * 1e-5, where);
    }
    // 1.55g - 0.55g³ in float: a few roundings of values below 1.
    k_errors.check(out[i].y, optics::schlick_k(lobe.g), 4e-7, where);
  }
}

// ---------------------------------------------------------------- light.glsl

TEST(OpticsTwin, SpotConeAcrossTheEdge) {
  std::mt19937 rng(1);
  std::vector<glm::vec4> in;
  std::vector<Light> lights;
  const float cones[] = {2.0f, 10.0f, 25.0f, 45.0f, 89.0f, 120.0f, 179.0f};
  const float edges[] = {0.0f, 0.5f, 1.0f, 5.0f};
  for (float cone : cones)
    for (float edge : edges) {
      if (edge >= cone) continue;
      Light light;
      light.type = LightType::spot;
      light.direction = random_unit(rng);
      light.cone_deg = cone;
      light.edge_deg = edge;
      // Directions at angles from cone - 2·edge to cone + edge/2 (or ±1° for the hard cut).
      const glm::vec3 side = glm::normalize(glm::cross(light.direction, random_unit(rng)));
      for (int j = 0; j < 200; ++j) {
        const float span = edge > 0 ? edge : 1.0f;
        const double angle = pi / 180 * (cone - 2 * span + 2.5 * span * j / 199.0);
        const glm::vec3 dir = glm::normalize(float(std::cos(angle)) * light.direction +
                                             float(std::sin(angle)) * side);
        in.emplace_back(light.direction, float(cone * pi / 180));
        in.emplace_back(dir, float(edge * pi / 180));
        lights.push_back(light);
      }
    }
  const auto out = run_twin("spot_cone.comp.glsl", in, 2, 1);

  Errors errors("spot_cone", false);
  for (size_t i = 0; i < lights.size(); ++i) {
    const Light& light = lights[i];
    // The C++ wants a unit dir: acos(axis·dir) turns |dir| - 1 ≈ ε into an angle
    // error ε/sin(angle), while the GPU's atan2 ignores |dir|.
    const glm::dvec3 dir = glm::normalize(glm::dvec3(in[2 * i + 1]));
    const double cpu = optics::spot_cone(light, dir);
    const double angle = std::acos(std::clamp(glm::dot(glm::normalize(glm::dvec3(light.direction)), dir), -1.0, 1.0));
    const double cone = light.cone_deg * pi / 180, edge = light.edge_deg * pi / 180;
    auto where = [&] { return "cone " + std::to_string(light.cone_deg) + " edge " + std::to_string(light.edge_deg) +
                              " angle " + std::to_string(angle * 180 / pi); };
    if (edge == 0.0) {
      // The hard cut is a step: within float rounding of the angle (~1e-6 rad:
      // the inputs' rounding, acos in C++ vs atan2 on the GPU) the two may disagree.
      if (std::abs(angle - cone) < 1e-6) {
        errors.finite(out[i].x, where);
        continue;
      }
      errors.check(out[i].x, cpu, 0.0, where);
    } else {
      // The angle agrees to ~1e-7 rad (float inputs and atan2); smoothstep's
      // slope is at most 1.5/edge.
      errors.check(out[i].x, cpu, 1e-6 + 1.5 * 4e-7 / (cone > 0 ? edge : 1.0), where);
    }
  }
}

// A small image with distinct texels, uploaded at the corner of layer `layer`
// of a larger 2D array texture with its rows flipped (the contract of
// sample_gobo in light.glsl: a gobo smaller than the array keeps its texels),
// the rest of the layer white so that reading past the gobo shows.
Texture upload_gobo(const Image& image, int layer, int layers) {
  const int width = image.width + 3, height = image.height + 2;
  Texture texture = make_texture(GL_TEXTURE_2D_ARRAY, GL_RGBA32F, width, height, layers);
  const std::vector<glm::vec4> white(size_t(width) * height, glm::vec4(1.0f));
  glTextureSubImage3D(texture.id(), 0, 0, 0, layer, width, height, 1, GL_RGBA, GL_FLOAT, white.data());
  std::vector<glm::vec4> rows(image.pixels.size());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) rows[size_t(image.height - 1 - y) * image.width + x] = glm::vec4(image.at(x, y), 1);
  glTextureSubImage3D(texture.id(), 0, 0, 0, layer, image.width, image.height, 1, GL_RGBA, GL_FLOAT, rows.data());
  // The sampling state must not matter (texelFetch): set the filtering the
  // uploader would set for texture() lookups.
  glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  return texture;
}

TEST(OpticsTwin, GoboCoordinatesAndSamplesAcrossTheSquare) {
  Context::headless();  // current before the texture upload (ctest runs each test alone)
  std::mt19937 rng(2);
  auto image = std::make_shared<Image>(7, 5);
  for (glm::vec3& p : image->pixels) p = glm::vec3(uniform(rng, 0, 1), uniform(rng, 0, 1), uniform(rng, 0, 1));
  const int layer = 1;
  const Texture texture = upload_gobo(*image, layer, 3);
  glBindTextureUnit(0, texture.id());

  std::vector<Light> lights;
  std::vector<glm::vec4> in;
  const float cones[] = {3.0f, 20.0f, 45.0f, 80.0f, 90.0f, 135.0f};
  for (float cone : cones)
    for (int l = 0; l < 4; ++l) {
      Light light;
      light.type = LightType::spot;
      light.cone_deg = cone;
      light.direction = l == 0 ? glm::vec3(0, -1, 0) : random_unit(rng);  // l = 0: the vertical default
      light.gobo_up = l == 0 ? glm::vec3(0, 0, 1) : glm::normalize(glm::cross(light.direction, random_unit(rng)));
      light.gobo = image;
      glm::dvec3 right_d, up_d;
      optics::gobo_frame(light, right_d, up_d);
      const glm::vec3 right(right_d), up(up_d);
      // tan_cone = 0 for cone >= 90°: no square (gobo_uv in light.glsl).
      const float tan_cone = cone < 90.0f ? float(std::tan(cone * pi / 180)) : 0.0f;
      for (int j = 0; j < 300; ++j) {
        // uv over [-0.25, 1.25]² (inside, across the edges, outside), and one
        // direction in eight behind the light's plane.
        const float u = uniform(rng, -0.25f, 1.25f), v = uniform(rng, -0.25f, 1.25f);
        const float t = tan_cone > 0 ? tan_cone : 1.0f;
        glm::vec3 dir = glm::normalize(light.direction + (2 * u - 1) * t * right + (2 * v - 1) * t * up);
        if (j % 8 == 7) dir = -dir;
        in.emplace_back(glm::normalize(light.direction), tan_cone);
        in.emplace_back(right, float(layer));
        in.emplace_back(up, 0.0f);
        in.emplace_back(dir, 0.0f);
        in.emplace_back(uniform(rng, -0.1f, 1.1f), uniform(rng, -0.1f, 1.1f), image->width, image->height);
        lights.push_back(light);
      }
    }
  // The texel centres and edges themselves, where the bilinear weights are 0 or ½.
  for (int x = 0; x <= 2 * image->width; ++x)
    for (int y = 0; y <= 2 * image->height; ++y) {
      for (int k = 0; k < 4; ++k) {
        const glm::vec4 first_case = in[k];  // copied: push_back may reallocate `in`
        in.push_back(first_case);
      }
      in.emplace_back(0.5f * x / image->width, 0.5f * y / image->height, image->width, image->height);
      const Light first_light = lights[0];
      lights.push_back(first_light);
    }
  const auto out = run_twin("gobo.comp.glsl", in, 5, 2);

  Errors uv_errors("gobo_uv", false), color_errors("sample_gobo", false);
  for (size_t i = 0; i < lights.size(); ++i) {
    const glm::vec4* args = &in[5 * i];
    const glm::dvec3 dir(args[3]);
    const glm::dvec2 uv = optics::gobo_uv(lights[i], dir);
    auto where = [&] { return "cone " + std::to_string(lights[i].cone_deg) + " dir " + str(args[3]); };
    // 0.5 + (d·right)·0.5/(z·tan): float dot products (~2ε) times the scale
    // 0.5/(z·tan) <= 40 for the directions generated (uv within 1.25, 3° cones).
    const double scale = 0.5 / (std::max(glm::dot(dir, glm::dvec3(args[0])), 1e-3) * std::max<double>(args[0].w, 1e-3));
    for (int c = 0; c < 2; ++c) uv_errors.check(out[2 * i][c], uv[c], 1e-6 + 1e-6 * scale, where);

    // sample_gobo at the given lookup uv; zero outside the unit square like the
    // C++ gobo colour. Bilinear weights in float: ~2ε of texel values <= 1.
    const glm::dvec2 lookup(args[4]);
    const bool inside = lookup.x >= 0 && lookup.x <= 1 && lookup.y >= 0 && lookup.y <= 1;
    const glm::dvec3 color = inside ? optics::sample_gobo(*image, lookup) : glm::dvec3(0.0);
    auto at = [&] { return "uv (" + std::to_string(lookup.x) + ", " + std::to_string(lookup.y) + ")"; };
    for (int c = 0; c < 3; ++c) color_errors.check(out[2 * i + 1][c], color[c], 1e-6, at);
  }
}

// beam_uv, beam_depth and inside_beam of random beams at points around them.
// Half of the beams are axis-aligned with points on a 1/8 grid (exact in
// float), so that points on a face are on it for both sides: the box is closed.
// The GPU's beam_interval of the ray x + t·ray.xyz, t in [0, ray.w], against
// optics::beam_interval: the length inside the box, whose ends move by the
// position's rounding over the ray's slope against each face (a ray grazing a
// face within 1/20 rad is checked for finiteness only: there the ends are
// ill-conditioned in any precision).
template <typename Describe>
void check_beam_interval(const Light& light, const glm::dvec3& x, const glm::vec4& ray, const glm::vec4& gpu,
                         double position, Errors& errors, Describe&& where) {
  const glm::dvec3 dir = glm::normalize(glm::dvec3(ray));
  const optics::Interval cpu = optics::beam_interval(light, x, dir, 0.0, ray.w);
  glm::dvec3 right, up;
  optics::gobo_frame(light, right, up);
  const double slope = std::min({std::abs(glm::dot(dir, right)), std::abs(glm::dot(dir, up)),
                                 std::abs(glm::dot(dir, glm::dvec3(light.direction)))});
  const double length = cpu.empty() ? 0.0 : cpu.hi - cpu.lo;
  const double gpu_length = gpu.x < gpu.y ? double(gpu.y) - gpu.x : 0.0;
  if (slope < 0.05) {
    errors.finite(gpu_length, where);
    return;
  }
  errors.check(gpu_length, length, 4.0 * position / slope + 1e-6 * ray.w, where);
}

TEST(OpticsTwin, BeamCoordinatesAndInside) {
  std::mt19937 rng(6);
  std::vector<Light> lights;
  std::vector<glm::vec4> in;
  for (int l = 0; l < 40; ++l) {
    const bool aligned = l % 2 == 0;
    Light light;
    light.type = LightType::directional;
    light.direction = aligned ? glm::vec3(0, -1, 0) : random_unit(rng);
    light.gobo_up = aligned ? glm::vec3(0, 0, 1) : random_unit(rng);  // aligned frame: right −x, up +z
    const glm::vec3 anywhere(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
    light.beam = Beam{aligned ? grid_point(rng) : anywhere,
                      aligned ? glm::vec2(0.25f * std::uniform_int_distribution<int>(1, 16)(rng), 0.5f)
                              : glm::vec2(uniform(rng, 0.2f, 5.0f), uniform(rng, 0.2f, 5.0f)),
                      aligned ? 2.0f : uniform(rng, 0.5f, 10.0f)};
    glm::dvec3 right, up;
    optics::gobo_frame(light, right, up);
    const Beam& b = *light.beam;
    for (int j = 0; j < 200; ++j) {
      // Around the box: u, v in [-0.3, 1.3], s in [-0.2, 1.2] of the length.
      const double u = uniform(rng, -0.3f, 1.3f), v = uniform(rng, -0.3f, 1.3f), s = uniform(rng, -0.2f, 1.2f);
      glm::vec3 x(glm::dvec3(b.origin) + (u - 0.5) * b.size.x * right + (v - 0.5) * b.size.y * up +
                  s * b.length * glm::dvec3(light.direction));
      if (aligned) x = glm::round(x * 8.0f) / 8.0f;
      in.emplace_back(b.origin, b.length);
      in.emplace_back(light.direction, b.size.x);
      in.emplace_back(glm::vec3(right), b.size.y);
      in.emplace_back(glm::vec3(up), 0.0f);
      in.emplace_back(x, 0.0f);
      in.emplace_back(random_unit(rng), uniform(rng, 0.1f, 20.0f));  // a ray from x, to t1
      lights.push_back(light);
    }
  }
  const auto out = run_twin("beam.comp.glsl", in, 6, 2);

  Errors uv_errors("beam_uv", false), depth_errors("beam_depth", false), inside_errors("inside_beam", false);
  Errors interval_errors("beam_interval", false);
  int boundary = 0;
  for (size_t i = 0; i < lights.size(); ++i) {
    const Light& light = lights[i];
    const Beam& b = *light.beam;
    const glm::dvec3 x(in[6 * i + 4]);
    auto where = [&] { return "beam origin " + str(b.origin) + " x " + str(in[6 * i + 4]); };
    // x − origin in float (~ε·(|x| + |origin|)) projected on the float frame
    // (~ε of each axis): 8ε·(|x| + |origin|) in position, over w or h in uv.
    const double position = 8 * 6e-8 * (glm::length(x) + glm::length(glm::dvec3(b.origin))) + 1e-7;
    const glm::dvec2 uv = optics::beam_uv(light, x);
    const double s = optics::beam_depth(light, x);
    const glm::vec4 uvs = out[2 * i], interval = out[2 * i + 1];
    uv_errors.check(uvs.x, uv.x, position / b.size.x, where);
    uv_errors.check(uvs.y, uv.y, position / b.size.y, where);
    depth_errors.check(uvs.z, s, position, where);
    check_beam_interval(light, x, in[6 * i + 5], interval, position, interval_errors, where);
    // Within rounding of a face the verdicts may differ (not on the aligned grid: exact there).
    const double margin = std::min({std::abs(uv.x), std::abs(1 - uv.x), std::abs(uv.y), std::abs(1 - uv.y)});
    const double across = margin * std::min(b.size.x, b.size.y), along = std::min(std::abs(s), std::abs(s - b.length));
    const bool near_face = std::min(across, along) < position;
    const bool exact = i / 200 % 2 == 0;
    if (near_face && !exact) {
      ++boundary;
      inside_errors.finite(uvs.w, where);
    } else {
      inside_errors.check(uvs.w, optics::inside_beam(light, x) ? 1.0 : 0.0, 0.0, where);
    }
  }
  std::printf("inside_beam: %d cases within rounding of a face left out\n", boundary);
}

TEST(OpticsTwin, FalloffOfBothLightModels) {
  std::vector<glm::vec4> in;
  const glm::vec2 a1_a0[] = {{1, 0}, {1, 1}, {0.25f, 0.5f}, {0, 1}, {2, 1e-3f}};
  for (int model = 0; model <= 1; ++model)
    for (const glm::vec2& a : a1_a0)
      for (int e = -80; e <= 30; ++e) {  // r from 1e-8 (inside the 1e-6 clamp) to 1e3
        const float r = float(std::pow(10.0, e / 10.0));
        in.emplace_back(float(model), r, a.x, a.y);
      }
  in.emplace_back(0.0f, 0.0f, 1.0f, 0.0f);  // r = 0: the light itself
  const auto out = run_twin("falloff.comp.glsl", in, 1, 1);

  Errors errors("light_falloff");
  for (size_t i = 0; i < in.size(); ++i) {
    Light light;  // a unit point light at the origin, seen from x at distance r
    light.intensity = glm::vec3(1.0f);
    LightModel model;
    model.type = static_cast<LightModelType>(int(in[i].x));
    model.a1 = in[i].z;
    model.a0 = in[i].w;
    const double cpu = optics::arrival(light, model, glm::dvec3(in[i].y, 0, 0)).irradiance.x;
    auto where = [&] { return "model " + std::to_string(int(in[i].x)) + " r " + std::to_string(in[i].y); };
    // Three roundings and a division: 1e-6 relative.
    errors.check(out[i].x, cpu, 1e-6 * cpu, where);
  }
}

// ---------------------------------------------------------------- media.glsl

TEST(OpticsTwin, BoxChordsAndTransmittance) {
  std::mt19937 rng(3);
  const glm::vec3 lo(-1.0f, -0.5f, -2.0f), hi(1.5f, 1.0f, 0.25f);
  std::vector<glm::vec4> in;
  for (int i = 0; i < 4000; ++i) {
    glm::vec3 a = grid_point(rng), b = grid_point(rng);
    switch (i % 5) {
      case 0: break;                                               // anywhere on the grid
      case 1: b = a; b[i % 3] = grid_point(rng)[i % 3]; break;     // axis-parallel
      case 2: a[i % 3] = lo[i % 3]; b[i % 3] = lo[i % 3]; break;   // in a face's plane: grazing
      case 3: a = glm::vec3(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3));
              b = glm::vec3(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3)); break;
      case 4: b = a + 1e-3f * random_unit(rng); break;             // short segments
    }
    const glm::vec3 ray = b == a ? random_unit(rng) : glm::normalize(b - a);
    const float sigma_t = uniform(rng, 0.0f, 10.0f), s = uniform(rng, 0.0f, 5.0f);
    in.emplace_back(a, sigma_t);
    in.emplace_back(b, s);
    in.emplace_back(lo, 0.0f);
    in.emplace_back(hi, 0.0f);
    in.emplace_back(ray, 0.0f);
  }
  const auto out = run_twin("media.comp.glsl", in, 5, 1);

  // A scene whose only extinction is the box with σt = 1: its optical depths are chords.
  Scene scene;
  Volume box;
  box.min = lo;
  box.max = hi;
  box.sigma_a = glm::vec3(1.0f);
  scene.volumes.push_back(box);
  Errors chords("box_chord", false), rays("box_ray_chord", false), contains("box_contains", false),
      trans("transmittance");
  for (size_t i = 0; i < out.size(); ++i) {
    const glm::vec4* args = &in[5 * i];
    const glm::dvec3 a(args[0]), b(args[1]);
    auto where = [&] { return "a " + str(args[0]) + " b " + str(args[1]) + " dir " + str(args[4]); };
    // Slab parameters in float: ~2ε relative of lengths up to ~10 m; a grazing
    // segment lies exactly in the face plane on both sides (grid inputs).
    chords.check(out[i].x, optics::optical_depth(scene, a, b).x, 4e-6, where);
    Light sun;
    sun.type = LightType::directional;
    sun.direction = -glm::vec3(args[4]);  // the leg runs toward the light, against its travel
    rays.check(out[i].y, optics::light_leg_depth(scene, sun, a).x, 4e-6, where);
    // Closed box, exact comparisons on both sides.
    const bool inside = glm::all(glm::greaterThanEqual(a, glm::dvec3(lo))) && glm::all(glm::lessThanEqual(a, glm::dvec3(hi)));
    contains.check(out[i].z, inside ? 1.0 : 0.0, 0.0, where);
    // GLSL exp: (3 + 2|x|) ulp (GLSL 4.50 §4.7.1); x = σt·s <= 50.
    const double x = double(args[0].w) * double(args[1].w), cpu = std::exp(-x);
    trans.check(out[i].w, cpu, cpu * (3 + 2 * x) * 1.2e-7, where);
  }
}

// ---------------------------------------------------------------- sun.glsl

// One case of sun.comp.glsl: F(u, v), the scalar airlight and the ray form.
struct SunCase {
  float sigma_s, sigma_t, I0, d_lv, gamma, d_vp, u, v;
  glm::vec3 origin, dir, light;
  float d;
};

TEST(OpticsTwin, SunFunctionAndAirlight) {
  std::mt19937 rng(4);
  auto log_uniform = [&](float lo_exp, float hi_exp) { return std::pow(10.0f, uniform(rng, lo_exp, hi_exp)); };
  std::vector<SunCase> cases;
  for (int i = 0; i < 4000; ++i) {
    SunCase c{};
    // F over the whole domain: u = 0, and u from 5e-7 to 50 (log-uniform); v
    // uniform in [0, π/2), and one in four within 1e-6..1e-1 of π/2.
    c.u = i % 50 == 0 ? 0.0f : 50.0f * log_uniform(-8, 0);
    const float gap = log_uniform(-6, -1);
    c.v = std::min(i % 4 == 0 ? float(pi / 2 - gap) : uniform(rng, 0, float(pi / 2)), std::nextafter(float(pi / 2), 0.0f));
    // Random media and geometries, optical depths σt·d_lv from 1e-5 to 1e4; one
    // in five rays nearly through the light (γ near 0 or π).
    c.sigma_t = log_uniform(-3, 1);
    c.sigma_s = c.sigma_t * uniform(rng, 0.05f, 1.0f);
    c.I0 = 100.0f;
    c.d_lv = log_uniform(-2, 3);
    c.gamma = uniform(rng, 0, float(pi));
    if (i % 5 == 1) c.gamma = log_uniform(-6, -1);
    if (i % 5 == 2) c.gamma = float(pi) - log_uniform(-6, -1);
    c.d_vp = log_uniform(-3, 3);
    c.origin = glm::vec3(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
    c.dir = random_unit(rng);
    c.light = c.origin + log_uniform(-2, 2) * random_unit(rng);
    if (i % 7 == 3) c.light = c.origin + uniform(rng, -3, 30) * c.dir;  // on (or within rounding of) the ray
    c.d = log_uniform(-3, 3);
    cases.push_back(c);
  }
  // The cancellation of F(A1, A2) − F(A1, γ/2) (docs/decisions.md, Numerics): σt·d_lv ≈ 8, γ > π/2.
  for (int i = 0; i < 64; ++i) {
    SunCase c = cases[i];
    c.sigma_t = 0.8f;
    c.d_lv = 10.0f;
    c.gamma = float(pi / 2 + (pi / 2) * i / 64.0);
    cases.push_back(c);
  }
  std::vector<glm::vec4> in;
  for (const SunCase& c : cases) {
    in.emplace_back(c.sigma_s, c.sigma_t, c.I0, c.d_lv);
    in.emplace_back(c.gamma, c.d_vp, c.u, c.v);
    in.emplace_back(c.origin, c.d);
    in.emplace_back(c.dir, 0.0f);
    in.emplace_back(c.light, 0.0f);
  }
  const auto out = run_twin("sun.comp.glsl", in, 5, 1);

  Errors f_errors("sun_F"), scalar_errors("sun_airlight"), ray_errors("sun_airlight_ray");
  for (size_t i = 0; i < cases.size(); ++i) {
    const SunCase& c = cases[i];
    auto where = [&] {
      return "u " + std::to_string(c.u) + " v " + std::to_string(c.v) + " σs " + std::to_string(c.sigma_s) +
             " σt " + std::to_string(c.sigma_t) + " d_lv " + std::to_string(c.d_lv) + " γ " +
             std::to_string(c.gamma) + " d_vp " + std::to_string(c.d_vp);
    };
    // The quadrature's error (12 + 12 nodes, over this domain) plus float
    // exp/tan of exponents up to 16: 1e-4.
    const double f = optics::sun_F(c.u, c.v);
    f_errors.check(out[i].x, f, 1e-4 * f, where);
    // The same quadrature on ranges from γ/2, bounds from float geometry. Its
    // worst case (quadrature, not rounding: it shrinks with more nodes) is a
    // long ray passing very close to the light, where part B holds both the
    // 1/r² tail and the extinction cut-off: 2e-4. Below 1e-30 (optical
    // depths > ~60) only finiteness. Within 1e-5 m of the ray the clamps differ
    // (the C++ clamps r at 1 µm, the twin r0): only finiteness.
    const double r0 = c.d_lv * std::abs(std::sin(double(c.gamma)));
    const double scalar = optics::sun_airlight(c.sigma_s, c.sigma_t, c.I0, c.d_lv, c.gamma, c.d_vp);
    if (r0 < 1e-5 || scalar < 1e-30)
      scalar_errors.finite(out[i].y, where);
    else
      scalar_errors.check(out[i].y, scalar, 2e-4 * scalar, where);
    const glm::dvec3 delta = glm::dvec3(c.light) - glm::dvec3(c.origin), dir(c.dir);
    const double ray_r0 = glm::length(delta - glm::dot(delta, dir) * dir);
    const double ray = optics::sun_airlight(c.sigma_s, c.sigma_t, c.I0, c.origin, dir, c.light, c.d);
    auto ray_where = [&] { return where() + " ray r0 " + std::to_string(ray_r0) + " d " + std::to_string(c.d); };
    // r0 = |Δ - xs·dir| in float: absolute error ~ε·|Δ|, so the relative error of
    // r0 (and of A0 ∝ 1/r0) is ~ε·|Δ|/r0: compared where r0 > 1e-3·|Δ|.
    if (ray >= 1e-30 && ray_r0 > 1e-3 * glm::length(delta))
      ray_errors.check(out[i].z, ray, 2e-4 * ray, ray_where);
    else
      ray_errors.finite(out[i].z, ray_where);
  }
}

}  // namespace
}  // namespace airlight::kit
