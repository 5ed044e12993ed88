// The GLSL twin of optics::cone_intervals (shaders/optics/light.glsl) against the
// C++ over every kind of line (optics/cone_test_cases.hpp).
#include "methods/kit/testing/twins/twin_test_support.hpp"
#include "optics/cone_test_cases.hpp"
#include "optics/light.hpp"

#include <gtest/gtest.h>

#include <map>

namespace airlight::kit {
namespace {

using namespace twin;

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
// measured use a small part of it (end/allowed in the table), and GLSL leaves
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

}  // namespace
}  // namespace airlight::kit
