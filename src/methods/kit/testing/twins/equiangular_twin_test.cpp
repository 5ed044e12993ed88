// The march's sample placement (methods/kit/sampling/equiangular.glsl) against its C++
// twin, and the twin against what equiangular steps promise: the 1/r² factor
// integrated exactly (Kulla & Fajardo 2012).
#include "methods/kit/sampling/equiangular.hpp"
#include "methods/kit/testing/twins/twin_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace airlight::kit {
namespace {

using namespace twin;

// Σ w/r² over the samples is (θb − θa)/h for any n: r² = h²/cos²θ at each sample.
TEST(EquiangularSteps, IntegrateInverseSquareExactly) {
  std::mt19937 rng(3);
  for (int c = 0; c < 200; ++c) {
    const glm::dvec3 eye(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
    const glm::dvec3 dir = glm::normalize(glm::dvec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
    // Lights from 0.1 mm to 1 m off the ray: the 1/r² peak from very narrow to wide.
    const glm::dvec3 off(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
    const glm::dvec3 light = eye + double(uniform(rng, 0, 10)) * dir + off * std::pow(10.0, uniform(rng, -4, 0));
    const double a = uniform(rng, 0, 5), b = a + uniform(rng, 0.01, 20);
    const Segment s = equiangular_segment(a, b, eye, dir, light);
    for (int n : {1, 7, 64}) {
      double sum = 0.0;
      for (int k = 0; k < n; ++k) {
        const glm::dvec2 t = segment_sample(s, (k + 0.5) / n, n);
        EXPECT_GE(t.x, a - 1e-9 * b);
        EXPECT_LE(t.x, b + 1e-9 * b);
        sum += t.y / (s.h * s.h + (t.x - s.foot) * (t.x - s.foot));  // w/r² with r² from the foot point
      }
      // Exact but for double rounding in tan, the weights and n additions.
      EXPECT_NEAR(sum, (s.theta_b - s.theta_a) / s.h, 1e-12 * sum) << "case " << c << " n " << n;
    }
  }
}

// A ray, a light up to 2 m off it and an interval [a, b] on it, for the twins.
struct RandomSegment {
  glm::vec3 eye, dir, light;
  float a, b;
};

RandomSegment random_segment(std::mt19937& rng) {
  RandomSegment g;
  g.eye = glm::vec3(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, -5, 5));
  g.dir = glm::normalize(glm::vec3(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1)));
  g.light = g.eye + uniform(rng, 0, 10) * g.dir + glm::vec3(uniform(rng, -2, 2), uniform(rng, -2, 2), uniform(rng, -2, 2));
  g.a = uniform(rng, 0, 5);
  g.b = g.a + uniform(rng, 0.1f, 20);
  return g;
}

// GLSL and C++ place the same samples with the same weights (float against double).
TEST(OpticsTwin, EquiangularSegmentAndSample) {
  std::mt19937 rng(11);
  std::vector<glm::vec4> in;
  for (int c = 0; c < 4000; ++c) {
    const RandomSegment g = random_segment(rng);
    const int n = 1 + c % 64;
    in.insert(in.end(), {glm::vec4(g.eye, g.a), glm::vec4(g.dir, g.b), glm::vec4(g.light, (c % n + 0.5f) / n),
                         glm::vec4(float(n), c % 5 == 0 ? 1.0f : 0.0f, 0.0f, 0.0f)});
  }
  const auto out = run_twin("equiangular.comp.glsl", in, 4, 1);
  Errors position("segment_sample x"), weight("segment_sample w"), angle("theta", false);
  for (size_t i = 0; i < out.size(); ++i) {
    const glm::vec4* c = &in[4 * i];
    const bool even = c[3].y != 0.0f;
    const Segment s = even ? uniform_segment(c[0].w, c[1].w)
                           : equiangular_segment(c[0].w, c[1].w, glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2]));
    const glm::dvec2 t = segment_sample(s, c[2].w, int(c[3].x));
    const auto describe = [&] { return "case " + std::to_string(i); };
    // float: tan near ±π/2 magnifies the angle's rounding by 1/cos²θ, which the
    // weight carries too; 1e-4 of the interval holds over these rays.
    const double scale = c[1].w;
    position.check(out[i].x, t.x, 1e-4 * scale, describe);
    weight.check(out[i].y, t.y, 1e-4 * std::max(std::abs(t.y), scale / c[3].x), describe);
    angle.check(out[i].z, s.theta_a, 1e-5, describe);
    angle.check(out[i].w, s.theta_b, 1e-5, describe);
  }
}

// The march's walk in θ (equiangular_walk: tan by the addition formula, a
// step at a time) against the C++ segment_sample at the same u, after up to
// 63 steps of every stride a march takes (interleaved's M² up to 64): its
// error grows by about a rounding a step, and stays within the direct
// sample's own tolerance.
TEST(OpticsTwin, EquiangularWalkMatchesTheDirectSample) {
  std::mt19937 rng(13);
  std::vector<glm::vec4> in;
  std::vector<std::pair<double, int>> u_n;  // the sample's u and n, for the C++ side
  for (int c = 0; c < 4000; ++c) {
    const RandomSegment g = random_segment(rng);
    const int stride = 1 + c % 64, steps = 1 + (c / 64) % 64, n = stride * steps;  // k < steps: inside (0, 1)
    const int k = c % steps;
    const float offset = uniform(rng, 0.0f, 1.0f);
    in.insert(in.end(), {glm::vec4(g.eye, g.a), glm::vec4(g.dir, g.b), glm::vec4(g.light, offset),
                         glm::vec4(float(n), float(stride), float(k), 0.0f)});
    u_n.emplace_back((k * stride + offset) / n, n);
  }
  const auto out = run_twin("equiangular_walk.comp.glsl", in, 4, 1);
  Errors position("walk x"), weight("walk w");
  for (size_t i = 0; i < out.size(); ++i) {
    const glm::vec4* c = &in[4 * i];
    const Segment s =
        equiangular_segment(c[0].w, c[1].w, glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2]));
    const glm::dvec2 t = segment_sample(s, u_n[i].first, u_n[i].second);
    const auto describe = [&] { return "case " + std::to_string(i); };
    const double scale = c[1].w;  // as EquiangularSegmentAndSample: 1e-4 of the interval
    position.check(out[i].x, t.x, 1e-4 * scale, describe);
    weight.check(out[i].y, t.y, 1e-4 * std::max(std::abs(t.y), scale / u_n[i].second), describe);
  }
}

}  // namespace
}  // namespace airlight::kit
