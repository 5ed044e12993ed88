// The GLSL optics twins (shaders/optics/*.glsl) against the C++ optics they
// mirror (src/optics/, itself tested against quadrature): each twin runs in a
// compute shader (src/gpu/twin_shaders/) on thousands of inputs, and every
// output must be finite and within the tolerance stated beside its check.
// The C++ works in double, the twins in float: "ε" below is 2^-24 ≈ 6e-8.
#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "optics/closed_form.hpp"
#include "optics/cone_test_cases.hpp"
#include "optics/light.hpp"
#include "optics/media.hpp"
#include "optics/phase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace airlight::gpu {
namespace {

constexpr double pi = std::numbers::pi;

// Runs gpu/twin_shaders/<shader> over inputs.size() / in_stride cases (the
// layout of twin_io.glsl) and returns out_stride vec4s per case.
std::vector<glm::vec4> run_twin(const std::string& shader, const std::vector<glm::vec4>& inputs,
                                int in_stride, int out_stride) {
  Context& context = Context::headless();
  const Program program = make_compute_program("gpu/twin_shaders/" + shader);
  const int count = static_cast<int>(inputs.size()) / in_stride;
  const Buffer in = make_buffer(inputs.size() * sizeof(glm::vec4), inputs.data());
  const size_t out_bytes = static_cast<size_t>(count) * out_stride * sizeof(glm::vec4);
  const Buffer out = make_buffer(out_bytes, nullptr);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  glUseProgram(program.id());
  set_uniform(program, "count", count);
  glDispatchCompute((count + 63) / 64, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> outputs(static_cast<size_t>(count) * out_stride);
  glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(out_bytes), outputs.data());
  context.check("twin " + shader);
  return outputs;
}

// Checks one function case by case and reports its worst errors (relative ones
// only for functions whose relative error means something: not for chords,
// coordinates or step-like factors). Failures print the case (the first few
// only, so a broken twin doesn't flood the log).
class Errors {
public:
  explicit Errors(std::string name, bool relative = true) : name_(std::move(name)), relative_(relative) {}
  ~Errors() {
    std::printf("%-20s %5d cases (%5d compared)  max abs %-9.3g", name_.c_str(), cases_, compared_, max_abs_);
    if (relative_) std::printf("  max rel %.3g", max_rel_);
    std::printf("\n");
  }

  // Requires a finite gpu value with |gpu - cpu| <= tolerance.
  template <typename Describe>
  void check(double gpu, double cpu, double tolerance, Describe&& describe) {
    if (!finite(gpu, describe)) return;
    ++compared_;
    const double err = std::abs(gpu - cpu);
    max_abs_ = std::max(max_abs_, err);
    if (cpu != 0.0) max_rel_ = std::max(max_rel_, err / std::abs(cpu));
    if (!(err <= tolerance)) fail(describe, "gpu " + std::to_string(gpu) + " cpu " + std::to_string(cpu) +
                                                " tolerance " + std::to_string(tolerance));
  }

  // Only requires a finite gpu value: where the C++ is no reference (stated at the call).
  template <typename Describe>
  bool finite(double gpu, Describe&& describe) {
    ++cases_;
    if (!std::isfinite(gpu)) fail(describe, "non-finite gpu value " + std::to_string(gpu));
    return std::isfinite(gpu);
  }

private:
  template <typename Describe>
  void fail(Describe&& describe, const std::string& what) {
    if (++failures_ <= 8) ADD_FAILURE() << name_ << ": " << what << " at " << describe();
  }

  std::string name_;
  bool relative_;
  int cases_ = 0, compared_ = 0, failures_ = 0;
  double max_abs_ = 0.0, max_rel_ = 0.0;
};

std::string str(const glm::vec3& v) {
  return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

glm::vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> n;
  for (;;) {
    const glm::vec3 v(n(rng), n(rng), n(rng));
    if (glm::dot(v, v) > 1e-6f) return glm::normalize(v);
  }
}

float uniform(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

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

// A cone_intervals case as the twin sees it: every input rounded to float and
// read back from the buffer the GPU read, so both sides clip the same line.
optics::testing::ConeCase as_read(const optics::testing::ConeCase& c, const glm::vec4* in) {
  optics::testing::ConeCase f = c;
  f.apex = glm::dvec3(in[0]);
  f.half_angle = in[0].w;
  f.axis = glm::dvec3(in[1]);
  f.t0 = in[1].w;
  f.origin = glm::dvec3(in[2]);
  f.t1 = in[2].w;
  f.dir = glm::dvec3(in[3]);
  return f;
}

std::vector<glm::dvec2> pieces(const optics::ConeIntervals& lit) {
  return {lit.piece.begin(), lit.piece.begin() + lit.count};
}

// Ascending piece list of the twin's output (count, then two pieces).
std::vector<glm::dvec2> pieces(const glm::vec4* out) {
  std::vector<glm::dvec2> p;
  for (int i = 0; i < std::clamp(int(out[0].x), 0, 2); ++i) p.emplace_back(out[1][2 * i], out[1][2 * i + 1]);
  return p;
}

// The length of the symmetric difference of two piece lists: Σ|Δ end| when
// their pieces pair up, and covers the cases where they don't.
double mismatch_length(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b) {
  double sum = 0.0;
  for (const glm::dvec2& p : a) sum += p.y - p.x;
  for (const glm::dvec2& p : b) sum += p.y - p.x;
  for (const glm::dvec2& p : a)
    for (const glm::dvec2& q : b) sum -= 2.0 * std::max(0.0, std::min(p.y, q.y) - std::max(p.x, q.x));
  return sum;
}

bool covers(const std::vector<glm::dvec2>& pieces, double t) {
  return std::any_of(pieces.begin(), pieces.end(), [&](const glm::dvec2& p) { return t >= p.x && t <= p.y; });
}

// Float rounding of cone_intervals: positions (w = origin - apex, foot + s, the
// midpoint w + t·dir) to a few ε·(|w| + |t|), which moves the surface by that
// much; and the angle (sin and cos of α, angle_between) to a few ε rad, which
// moves it by |v|·that at distance |v| from the apex. 16ε each: the ends
// measured use at most 6% of it (end/allowed in the table), and GLSL leaves
// the precision of sin and cos open, so other drivers may need more than
// llvmpipe.
struct ConeRounding {
  static constexpr double eps = 6e-8, angle = 16 * eps;
  static double position(const optics::testing::ConeCase& c, double t) {
    return 16 * eps * (glm::length(c.origin - c.apex) + std::abs(t));
  }
  static double distance_from_apex(const optics::testing::ConeCase& c, double t) {
    return glm::length(c.origin + t * c.dir - c.apex);
  }
  // How far the float boundary near t may lie from the double one: the
  // surface's displacement over the sine of the crossing angle (at most the
  // whole segment: a grazing end).
  static double boundary(const optics::testing::ConeCase& c, double t) {
    const double moved = position(c, t) + distance_from_apex(c, t) * angle;
    return std::min(moved / optics::testing::crossing_sine(c, t), c.t1 - c.t0);
  }
  // Is the verdict at t beyond rounding (the angle off by more than float's error)?
  static bool clear(const optics::testing::ConeCase& c, double t) {
    const double slack = position(c, t) / distance_from_apex(c, t) + angle;
    return std::abs(optics::testing::angle_off_axis(c, t) - c.half_angle) > slack;
  }
};

// The mismatch the rounding allows: each boundary of either side may move by
// ConeRounding::boundary (`ends`), and a stretch between the C++'s boundaries
// whose middle is within rounding of the surface (a line on the cone) may flip
// whole (`flips`).
struct Allowed {
  double ends = 0.0, flips = 0.0;
};
Allowed allowed_mismatch(const optics::testing::ConeCase& c, const std::vector<glm::dvec2>& cpu,
                         const std::vector<glm::dvec2>& gpu) {
  std::vector<double> bounds{c.t0, c.t1};
  Allowed allowed;
  for (const auto* side : {&cpu, &gpu})
    for (const glm::dvec2& p : *side)
      for (double b : {p.x, p.y}) {
        if (b > c.t0 && b < c.t1) allowed.ends += ConeRounding::boundary(c, b);
        if (side == &cpu) bounds.push_back(b);
      }
  std::sort(bounds.begin(), bounds.end());
  for (size_t i = 0; i + 1 < bounds.size(); ++i)
    if (!ConeRounding::clear(c, 0.5 * (bounds[i] + bounds[i + 1]))) allowed.flips += bounds[i + 1] - bounds[i];
  return allowed;
}

// The worst results of one kind of case.
struct ConeWorst {
  int cases = 0, paired = 0, flipping = 0;
  double mismatch = 0.0;  // mismatch / allowed, in cases without flips
  double end = 0.0;       // |Δ end| / ConeRounding::boundary where the pieces pair up, but
                          // for grazing ends (allowed the whole segment)
  double relative = 0.0;  // |Δ end|·sin / (|w| + |t|) there, for ends crossed at sin >= 0.01
};

void record_ends(const optics::testing::ConeCase& c, const std::vector<glm::dvec2>& cpu,
                 const std::vector<glm::dvec2>& gpu, ConeWorst& w) {
  if (cpu.size() != gpu.size()) return;
  ++w.paired;
  for (size_t p = 0; p < cpu.size(); ++p)
    for (int e = 0; e < 2; ++e) {
      const double t = cpu[p][e], error = std::abs(gpu[p][e] - t);
      if (t == c.t0 || t == c.t1) continue;
      const double allowed = ConeRounding::boundary(c, t);
      if (allowed < c.t1 - c.t0) w.end = std::max(w.end, error / allowed);  // not a grazing end
      const double sine = optics::testing::crossing_sine(c, t);
      if (sine >= 0.01) w.relative = std::max(w.relative, error * sine / (glm::length(c.origin - c.apex) + std::abs(t)));
    }
}

TEST(OpticsTwin, ConeIntervalsOfEveryKindOfLine) {
  // The cases of the C++ test (optics/cone_test_cases.hpp: generic, apex behind
  // the eye, along the axis, through the apex, wide, parallel to a generator,
  // tangent, narrow, from the apex), rounded to float. Pieces are compared as
  // sets: the length of their symmetric difference (Σ|Δ end| when the pieces
  // pair up) must stay within what float rounding of each end allows
  // (allowed_mismatch), which grows without bound where an end is
  // tangent-degenerate; there the verdicts at 64 points, wherever they are
  // beyond rounding, must still agree.
  const std::vector<optics::testing::ConeCase> cases = optics::testing::ConeCaseMaker(12).make(9 * 1000);
  std::vector<glm::vec4> in;
  for (const optics::testing::ConeCase& c : cases) {
    in.emplace_back(glm::vec3(c.apex), float(c.half_angle));
    in.emplace_back(glm::vec3(c.axis), float(c.t0));
    in.emplace_back(glm::vec3(c.origin), float(c.t1));
    in.emplace_back(glm::vec3(c.dir), 0.0f);
  }
  const auto out = run_twin("cone.comp.glsl", in, 4, 2);

  std::map<std::string, ConeWorst> worst;
  Errors ends("cone_intervals", false), flips("cone_intervals flip", false), verdicts("cone verdicts", false);
  for (size_t i = 0; i < cases.size(); ++i) {
    const optics::testing::ConeCase c = as_read(cases[i], &in[4 * i]);
    const std::vector<glm::dvec2> cpu = pieces(c.clip()), gpu = pieces(&out[2 * i]);
    auto where = [&] { return c.kind + " case " + std::to_string(i); };
    const Allowed allowed = allowed_mismatch(c, cpu, gpu);
    const double mismatch = mismatch_length(cpu, gpu);
    (allowed.flips > 0.0 ? flips : ends).check(mismatch, 0.0, allowed.ends + allowed.flips, where);
    for (int k = 0; k < 64; ++k) {
      const double t = c.t0 + (k + 0.5) / 64 * (c.t1 - c.t0);
      auto at = [&] { return where() + " t " + std::to_string(t); };
      if (ConeRounding::clear(c, t)) verdicts.check(covers(gpu, t), covers(cpu, t), 0.0, at);
    }
    ConeWorst& w = worst[c.kind];
    ++w.cases;
    w.flipping += allowed.flips > 0.0;
    if (mismatch > 0.0 && allowed.flips == 0.0) w.mismatch = std::max(w.mismatch, mismatch / allowed.ends);
    record_ends(c, cpu, gpu, w);
  }
  std::printf("%-24s %5s %8s %6s %16s %13s %13s\n", "kind", "cases", "flipping", "paired", "mismatch/allowed",
              "end/allowed", "end relative");
  for (const auto& [kind, w] : worst)
    std::printf("%-24s %5d %8d %6d %16.3f %13.3f %13.2e\n", kind.c_str(), w.cases, w.flipping, w.paired, w.mismatch,
                w.end, w.relative);
}

// A small image with distinct texels, uploaded as the layer `layer` of a 2D
// array texture with its rows flipped (the contract of sample_gobo in light.glsl).
Texture upload_gobo(const Image& image, int layer, int layers) {
  Texture texture = make_texture(GL_TEXTURE_2D_ARRAY, GL_RGBA32F, image.width, image.height, layers);
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
        in.emplace_back(uniform(rng, -0.1f, 1.1f), uniform(rng, -0.1f, 1.1f), 0.0f, 0.0f);
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
      in.emplace_back(0.5f * x / image->width, 0.5f * y / image->height, 0.0f, 0.0f);
      const Light first_light = lights[0];
      lights.push_back(first_light);
    }
  const auto out = run_twin("gobo.comp.glsl", in, 5, 2);

  Errors uv_errors("gobo_uv", false), colour_errors("sample_gobo", false);
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
    const glm::dvec3 colour = inside ? optics::sample_gobo(*image, lookup) : glm::dvec3(0.0);
    auto at = [&] { return "uv (" + std::to_string(lookup.x) + ", " + std::to_string(lookup.y) + ")"; };
    for (int c = 0; c < 3; ++c) colour_errors.check(out[2 * i + 1][c], colour[c], 1e-6, at);
  }
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

// Segment endpoints on a 1/8 grid (exact in float, so "on the face" and "axis
// parallel" mean the same to both sides) plus random ones.
glm::vec3 grid_point(std::mt19937& rng) {
  std::uniform_int_distribution<int> n(-24, 24);
  return glm::vec3(n(rng), n(rng), n(rng)) / 8.0f;
}

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
  // The cancellation trap of the seeds README: σt·d_lv ≈ 8, γ > π/2.
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
    // Quadrature ≤ 1.1e-5 relative (12 + 12 nodes, measured in float on the
    // CPU over this domain), plus float exp/tan of exponents up to 16: 1e-4.
    const double f = optics::sun_F(c.u, c.v);
    f_errors.check(out[i].x, f, 1e-4 * f, where);
    // The same quadrature on ranges from γ/2, bounds from float geometry. Its
    // worst case, ~7e-5 (9e-6 with 16 nodes: quadrature, not rounding),
    // is a long ray passing within ~1e-4 rad of the light, where part B holds
    // both the 1/r² tail and the extinction cut-off: 2e-4. Below 1e-30 (optical
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
}  // namespace airlight::gpu
