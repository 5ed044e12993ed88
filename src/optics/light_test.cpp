#include "optics/light.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "optics/cone_test_cases.hpp"
#include "optics/test_support.hpp"

namespace airlight::optics {
namespace {

double rad(double deg) { return deg * std::numbers::pi / 180.0; }

Light spot(float cone_deg, float edge_deg) {
  Light l;
  l.type = LightType::spot;
  l.position = {0, 5, 0};
  l.direction = {0, -1, 0};
  l.intensity = glm::vec3(100.0f);
  l.cone_deg = cone_deg;
  l.edge_deg = edge_deg;
  l.gobo_up = {0, 0, 1};
  return l;
}

// A unit direction at `deg` from the axis -y, tilted toward +x.
glm::dvec3 off_axis(double deg) { return {std::sin(rad(deg)), -std::cos(rad(deg)), 0.0}; }

TEST(Spot, HardCone) {
  const Light l = spot(30.0f, 0.0f);  // Nilsson eq. 2.9: <= cone lit
  EXPECT_EQ(spot_cone(l, off_axis(0.0)), 1.0);
  EXPECT_EQ(spot_cone(l, off_axis(29.999)), 1.0);
  EXPECT_EQ(spot_cone(l, off_axis(30.001)), 0.0);
  EXPECT_EQ(spot_cone(l, off_axis(120.0)), 0.0);
}

TEST(Spot, SmoothEdge) {
  // smoothstep(t) = t²(3 - 2t), t = (cone - angle)/edge; 1e-9: angle round trip.
  const Light l = spot(30.0f, 10.0f);
  EXPECT_EQ(spot_cone(l, off_axis(19.9)), 1.0);
  EXPECT_NEAR(spot_cone(l, off_axis(22.5)), 0.84375, 1e-9);  // t = 0.75
  EXPECT_NEAR(spot_cone(l, off_axis(25.0)), 0.5, 1e-9);      // t = 0.5
  EXPECT_NEAR(spot_cone(l, off_axis(27.5)), 0.15625, 1e-9);  // t = 0.25
  EXPECT_EQ(spot_cone(l, off_axis(30.1)), 0.0);
}

TEST(Gobo, AxisAndConeBoundary) {
  // Frame: axis -y, up (0,0,1) → right = axis × up = (-1, 0, 0), up' = right × axis = (0, 0, 1).
  const Light l = spot(30.0f, 0.0f);
  const glm::dvec2 centre = gobo_uv(l, {0, -1, 0});
  EXPECT_NEAR(centre.x, 0.5, 1e-15);
  EXPECT_NEAR(centre.y, 0.5, 1e-15);
  const double c = rad(30.0);
  const glm::dvec3 axis(0, -1, 0), right(-1, 0, 0), up(0, 0, 1);
  const glm::dvec2 r = gobo_uv(l, std::cos(c) * axis + std::sin(c) * right);
  EXPECT_NEAR(r.x, 1.0, 1e-7);  // 1e-7: cone_deg is a float
  EXPECT_NEAR(r.y, 0.5, 1e-15);
  const glm::dvec2 u = gobo_uv(l, std::cos(c) * axis + std::sin(c) * up);
  EXPECT_NEAR(u.x, 0.5, 1e-15);
  EXPECT_NEAR(u.y, 1.0, 1e-7);
  const glm::dvec2 behind = gobo_uv(l, {0, 1, 0});
  EXPECT_TRUE(behind.x < 0.0 || behind.x > 1.0);
}

Image two_by_two() {
  Image img(2, 2);
  img.at(0, 0) = {1, 0, 0};  // top left
  img.at(1, 0) = {0, 1, 0};  // top right
  img.at(0, 1) = {0, 0, 1};  // bottom left
  img.at(1, 1) = {1, 1, 1};  // bottom right
  return img;
}

TEST(Gobo, BilinearWithPixelCentresAndClampToEdge) {
  const Image img = two_by_two();
  auto expect = [](glm::dvec3 a, glm::dvec3 b) {
    EXPECT_NEAR(glm::length(a - b), 0.0, 1e-12);  // exact up to rounding
  };
  expect(sample_gobo(img, {0.25, 0.75}), {1, 0, 0});  // top-left pixel centre (v = 1 is the top)
  expect(sample_gobo(img, {0.75, 0.25}), {1, 1, 1});
  expect(sample_gobo(img, {0.5, 0.5}), {0.5, 0.5, 0.5});
  expect(sample_gobo(img, {0.0, 1.0}), {1, 0, 0});    // clamp to edge
  expect(sample_gobo(img, {0.5, 1.0}), {0.5, 0.5, 0.0});
}

TEST(Light, RadiantIntensityAppliesConeAndGobo) {
  Light l = spot(30.0f, 0.0f);
  l.gobo = std::make_shared<Image>(two_by_two());
  // Toward gobo_up (+z) and right (-x): the top-right texel (green) region.
  const double a = rad(20.0);
  const glm::dvec3 dir = glm::normalize(glm::dvec3(-std::tan(a), -1.0, std::tan(a)));
  const glm::dvec3 I = radiant_intensity(l, dir);
  EXPECT_NEAR(I.x, 0.0, 1e-9);
  EXPECT_NEAR(I.y, 100.0, 1e-9);
  EXPECT_NEAR(I.z, 0.0, 1e-9);
  EXPECT_EQ(radiant_intensity(l, off_axis(40.0)), glm::dvec3(0.0));  // outside the cone
}

TEST(Light, ArrivalModels) {
  Light l;
  l.position = {0, 3, 4};
  l.intensity = glm::vec3(50.0f);
  const Arrival phys = arrival(l, LightModel{}, {0, 0, 0});
  EXPECT_NEAR(phys.irradiance.x, 50.0 / 25.0, 1e-12);  // I/r²
  EXPECT_NEAR(phys.distance, 5.0, 1e-12);
  EXPECT_NEAR(phys.to_light.z, 0.8, 1e-12);
  const LightModel simple{LightModelType::simplified, 2.0f, 0.5f};
  EXPECT_NEAR(arrival(l, simple, {0, 0, 0}).irradiance.x, 50.0 / (0.5 * 25 + 2), 1e-12);  // eq. 2.13

  Light sun;
  sun.type = LightType::directional;
  sun.direction = {0, -1, 0};
  sun.irradiance = glm::vec3(2.0f);
  const Arrival s = arrival(sun, LightModel{}, {1, 2, 3});
  EXPECT_EQ(s.irradiance, glm::dvec3(2.0));
  EXPECT_TRUE(std::isinf(s.distance));
  EXPECT_EQ(s.to_light, glm::dvec3(0, 1, 0));

  // At the light itself r is clamped at min_light_distance: finite, no NaN.
  const Arrival at = arrival(l, LightModel{}, glm::dvec3(l.position));
  EXPECT_NEAR(at.irradiance.x, 50.0 / (min_light_distance * min_light_distance), 1e-3);
  EXPECT_TRUE(std::isfinite(glm::length(at.to_light)));
}

// ------------------------------------------------------------ beams

// A vertical beam whose frame is the spot's above: right = (-1, 0, 0), up =
// (0, 0, 1). The aperture, 2 m along right by 1 m along up, is centred at
// (1, 4, 2); 5 m long: the box x ∈ [0, 2], y ∈ [-1, 4], z ∈ [1.5, 2.5].
Light vertical_beam() { return testing::beam_light({0, -1, 0}, {0, 0, 1}, Beam{{1, 4, 2}, {2, 1}, 5}, 3.0f); }

void expect_uv(const glm::dvec2& uv, double u, double v) {
  EXPECT_NEAR(uv.x, u, 1e-15);  // exact up to rounding: inputs are binary fractions
  EXPECT_NEAR(uv.y, v, 1e-15);
}

TEST(Beam, CoordinatesAcrossTheApertureAndDepth) {
  const Light l = vertical_beam();
  expect_uv(beam_uv(l, {1, 4, 2}), 0.5, 0.5);
  expect_uv(beam_uv(l, {0, 4, 2}), 1.0, 0.5);       // along right (-x) by w/2
  expect_uv(beam_uv(l, {1, 0, 2.5}), 0.5, 1.0);     // along up (+z) by h/2: v = 1, the top row
  expect_uv(beam_uv(l, {1.5, 2, 1.75}), 0.25, 0.25);
  EXPECT_NEAR(beam_depth(l, {1.5, 2, 1.75}), 2.0, 1e-15);
  EXPECT_NEAR(beam_depth(l, {7, 6, -3}), -2.0, 1e-15);  // upstream of the aperture
}

TEST(Beam, InsideIsTheClosedBox) {
  const Light l = vertical_beam();
  for (const glm::dvec3& in : {glm::dvec3(1, 4, 2), glm::dvec3(1, -1, 2), glm::dvec3(0, 2, 2.5),
                               glm::dvec3(2, -1, 1.5), glm::dvec3(0.3, 1, 1.9)})
    EXPECT_TRUE(inside_beam(l, in)) << in.x << ", " << in.y << ", " << in.z;
  for (const glm::dvec3& out : {glm::dvec3(1, 4.001, 2), glm::dvec3(1, -1.001, 2), glm::dvec3(2.001, 2, 2),
                                glm::dvec3(-0.001, 2, 2), glm::dvec3(1, 2, 1.499), glm::dvec3(1, 2, 2.501)})
    EXPECT_FALSE(inside_beam(l, out)) << out.x << ", " << out.y << ", " << out.z;
}

TEST(Beam, LightMapAndArrivalCarryTheBoxAndTheGobo) {
  Light l = vertical_beam();
  EXPECT_EQ(light_map(l, {1, 0, 2}), glm::dvec3(1.0));  // inside, no gobo
  EXPECT_EQ(light_map(l, {1, 5, 2}), glm::dvec3(0.0));  // upstream
  l.gobo = std::make_shared<Image>(two_by_two());
  // uv (0.75, 0.75) is the top-right texel's centre (green): x = 1 - 0.25·2, z = 2 + 0.25·1.
  const glm::dvec3 x(0.5, 1.0, 2.25);
  EXPECT_NEAR(glm::length(light_map(l, x) - glm::dvec3(0, 1, 0)), 0.0, 1e-12);
  const Arrival a = arrival(l, LightModel{}, x);
  EXPECT_NEAR(glm::length(a.irradiance - glm::dvec3(0, 3, 0)), 0.0, 1e-12);
  EXPECT_EQ(a.to_light, glm::dvec3(0, 1, 0));
  EXPECT_TRUE(std::isinf(a.distance));
  EXPECT_EQ(arrival(l, LightModel{}, {3, 1, 2}).irradiance, glm::dvec3(0.0));  // beside the beam
  // The simplified model changes nothing for a directional light (no falloff).
  EXPECT_EQ(arrival(l, LightModel{LightModelType::simplified, 0.5f, 2.0f}, x).irradiance, a.irradiance);
  // Without a beam a directional light (even with a stray gobo) reaches everywhere.
  l.beam.reset();
  EXPECT_EQ(light_map(l, {1, 5, 2}), glm::dvec3(1.0));
}

TEST(Light, LightMapOfSpotAndPointLights) {
  Light s = spot(30.0f, 0.0f);
  s.gobo = std::make_shared<Image>(two_by_two());
  const glm::dvec3 x(-0.5, 2.0, 0.7);
  const glm::dvec3 dir = glm::normalize(x - glm::dvec3(s.position));
  // I(ω) = intensity · light map; 1e-12: normalize and v / |v| round differently.
  EXPECT_NEAR(glm::length(light_map(s, x) * 100.0 - radiant_intensity(s, dir)), 0.0, 1e-12);
  EXPECT_GT(light_map(s, x).y, 0.0);
  EXPECT_EQ(light_map(s, {3, 0, 0}), glm::dvec3(0.0));              // outside the cone
  EXPECT_TRUE(std::isfinite(light_map(s, glm::dvec3(s.position)).x));  // at the apex: the axis
  EXPECT_EQ(light_map(testing::point_light({1, 2, 3}, 5.0f), x), glm::dvec3(1.0));
}

void expect_interval(const Interval& in, double lo, double hi, const char* what) {
  EXPECT_NEAR(in.lo, lo, 1e-12) << what;  // exact up to rounding
  EXPECT_NEAR(in.hi, hi, 1e-12) << what;
}

TEST(Beam, IntervalsOfSimpleLines) {
  const Light l = vertical_beam();
  const glm::dvec3 x(1, 0, 0), y(0, 1, 0);
  expect_interval(beam_interval(l, {-5, 2, 2}, x, 0, 20), 5, 7, "across, along +x");
  expect_interval(beam_interval(l, {-5, 2, 2}, x, 0, 6), 5, 6, "clipped by t1");
  expect_interval(beam_interval(l, {-5, 2, 2.5}, x, 0, 20), 5, 7, "in the plane of the up face: closed");
  expect_interval(beam_interval(l, {1, 10, 2}, -y, 0, 20), 6, 11, "down the axis through both ends");
  expect_interval(beam_interval(l, {1, 2, 2}, y, 0, 20), 0, 2, "from inside back up to the aperture");
  EXPECT_TRUE(beam_interval(l, {-5, 2, 3}, x, 0, 20).empty()) << "beside the box";
  EXPECT_TRUE(beam_interval(l, {-5, 2, 2.5001}, x, 0, 20).empty()) << "just off the up face";
  EXPECT_TRUE(beam_interval(l, {-5, 2, 2}, x, 0, 4).empty()) << "ends before the box";
  EXPECT_TRUE(beam_interval(l, {-5, 2, 2}, x, 6, 6).empty()) << "empty range";
}

// Random tilted beams and lines, among them lines along the frame's axes
// (parallel to faces to rounding): every sample whose inside_beam verdict is
// more than 1e-9 m from an end must agree with the interval, which is never NaN.
TEST(Beam, IntervalsMatchSamplingOfInsideBeam) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto random_vector = [&] { return glm::dvec3(u(rng), u(rng), u(rng)); };
  constexpr int samples = 2000;
  int mismatches = 0, lines_inside = 0;
  for (int i = 0; i < 600; ++i) {
    const glm::dvec3 direction = glm::normalize(random_vector() + glm::dvec3(0, 0.1, 0));
    const Beam beam{glm::vec3(3.0 * random_vector()), {0.5 + 2.0 * (u(rng) + 1), 0.5 + 2.0 * (u(rng) + 1)},
                    float(1.0 + 4.0 * (u(rng) + 1))};
    const Light l = testing::beam_light(glm::vec3(direction), glm::vec3(random_vector()), beam, 1.0f);
    glm::dvec3 right, up;
    gobo_frame(l, right, up);
    const glm::dvec3 axes[] = {right, up, glm::dvec3(glm::normalize(l.direction))};
    const glm::dvec3 dir = i % 2 ? glm::normalize(random_vector()) : (i % 4 ? 1.0 : -1.0) * axes[i / 2 % 3];
    // Origins near the box: its centre plus up to its size in every direction.
    const glm::dvec3 centre = glm::dvec3(beam.origin) + 0.5 * beam.length * axes[2];
    const glm::dvec3 origin = centre + 0.5 * double(beam.size.x) * u(rng) * right +
                              0.5 * double(beam.size.y) * u(rng) * up + 0.5 * double(beam.length) * u(rng) * axes[2] -
                              10.0 * dir;
    const double t0 = 0.0, t1 = 20.0;
    const Interval in = beam_interval(l, origin, dir, t0, t1);
    ASSERT_FALSE(std::isnan(in.lo) || std::isnan(in.hi)) << "case " << i;
    if (!in.empty()) {
      ++lines_inside;
      EXPECT_GE(in.lo, t0);
      EXPECT_LE(in.hi, t1);
    }
    for (int k = 0; k < samples; ++k) {
      const double t = t0 + (t1 - t0) * (k + 0.5) / samples;
      if (!in.empty() && std::min(std::abs(t - in.lo), std::abs(t - in.hi)) < 1e-9) continue;
      const bool within = !in.empty() && t >= in.lo && t <= in.hi;
      if (inside_beam(l, origin + t * dir) != within && ++mismatches <= 8)
        ADD_FAILURE() << "case " << i << " t " << t << " interval [" << in.lo << ", " << in.hi << "]";
    }
  }
  EXPECT_GT(lines_inside, 300);  // the cases do cross the box
}

// ------------------------------------------------------------ cone_intervals

bool covers(const ConeIntervals& lit, double t) {
  for (int i = 0; i < lit.count; ++i)
    if (t >= lit.piece[i].x && t <= lit.piece[i].y) return true;
  return false;
}

double covered_length(const ConeIntervals& lit) {
  double sum = 0.0;
  for (int i = 0; i < lit.count; ++i) sum += lit.piece[i].y - lit.piece[i].x;
  return sum;
}

void expect_pieces(const ConeIntervals& lit, const std::vector<glm::dvec2>& want, const char* what) {
  ASSERT_EQ(lit.count, int(want.size())) << what;
  for (int i = 0; i < lit.count; ++i) {
    EXPECT_NEAR(lit.piece[i].x, want[i].x, 1e-12) << what;  // exact up to rounding
    EXPECT_NEAR(lit.piece[i].y, want[i].y, 1e-12) << what;
  }
}

TEST(ConeIntervals, PiecesOfSimpleLines) {
  const glm::dvec3 o(0.0), z(0, 0, 1), x(1, 0, 0);
  const double q = std::numbers::pi / 4;
  expect_pieces(cone_intervals(o, z, q, {-2, 0, 1}, x, 0, 4), {{1, 3}}, "across a 45° cone at z = 1: |x| <= 1");
  expect_pieces(cone_intervals(o, z, q, {-2, 0, -1}, x, 0, 4), {}, "across the dark backward nappe");
  expect_pieces(cone_intervals(o, z, q, {0, 0, -2}, z, 0, 5), {{2, 5}}, "along the axis, apex at t = 2");
  expect_pieces(cone_intervals(o, z, q, {0, 0, 2}, -z, 0, 5), {{0, 2}}, "against the axis toward the apex");
  const glm::dvec3 d30(std::sin(rad(30)), 0, std::cos(rad(30))), d60(std::sin(rad(60)), 0, std::cos(rad(60)));
  expect_pieces(cone_intervals(o, z, q, -2.0 * d30, d30, 0, 5), {{2, 5}}, "through the apex at 30°");
  expect_pieces(cone_intervals(o, z, q, -2.0 * d60, d60, 0, 5), {}, "through the apex at 60°: the apex alone");
  expect_pieces(cone_intervals(o, z, 3 * q, {-2, 0, -1}, x, 0, 4), {{0, 1}, {3, 4}},
                "135°: dark only in the backward 45° cone");
  expect_pieces(cone_intervals(o, z, 3 * q, {0, 0, -2}, z, 0, 5), {{2, 5}}, "135°, along the axis");
  expect_pieces(cone_intervals(o, z, 2 * q, {0, 0, -2}, glm::normalize(glm::dvec3(1, 0, 1)), 0, 5),
                {{2 * std::sqrt(2.0), 5}}, "90°: the half-space z >= 0");
  expect_pieces(cone_intervals(o, z, 4 * q, {0, 0, -2}, z, 0, 5), {{0, 5}}, "180°: everything");
  const glm::dvec3 g = glm::normalize(glm::dvec3(1, 0, 1));  // a generator of the 45° cone
  expect_pieces(cone_intervals(o, z, q, glm::dvec3(0, 0, 1) - 2.0 * g, g, 0, 5), {{2 - std::sqrt(0.5), 5}},
                "parallel to a generator: one crossing, where |s| = 1 + s at s = (t - 2)/√2");
  expect_pieces(cone_intervals(o, z, q, {1, -2, 1}, {0, 1, 0}, 0, 4), {}, "tangent at (1, 0, 1): a point");
  expect_pieces(cone_intervals(o, z, q, {-2, 0, 1}, x, 3, 3), {}, "an empty segment");
}

// What a brute-force sampling of one case found.
struct Sampled {
  int mismatches = 0;    // samples where spot_cone and the pieces disagree beyond rounding
  int ambiguous = 0;     // samples whose spot_cone verdict is within rounding
  int transitions = 0;   // changes of spot_cone between neighbouring samples
  double length = 0.0;   // sample spacing × lit samples
};

// Is spot_cone's verdict at t beyond the rounding of the double geometry? The
// angle at x = origin + t·dir is off by ~1e-16·(|origin| + |apex| + |t|)/|x - apex|.
bool clear_margin(const testing::ConeCase& c, double t) {
  const glm::dvec3 v = c.origin + t * c.dir - c.apex;
  const double size = glm::length(c.origin) + glm::length(c.apex) + std::abs(t);
  return std::abs(testing::angle_off_axis(c, t) - c.half_angle) > 1e-13 * size / glm::length(v) + 1e-13;
}

// The reference: spot_cone of the case's hard-cut spot toward x = origin + t·dir.
bool spot_lit(const testing::ConeCase& c, double t) {
  const glm::dvec3 v = c.origin + t * c.dir - glm::dvec3(c.spot.position);
  return spot_cone(c.spot, glm::length(v) > 0.0 ? glm::normalize(v) : v) == 1.0;
}

Sampled sample(const testing::ConeCase& c, const ConeIntervals& lit, int n) {
  const double h = (c.t1 - c.t0) / n;
  Sampled s;
  bool previous = false;
  for (int k = 0; k < n; ++k) {
    const double t = c.t0 + (k + 0.5) * h;
    const bool ref = spot_lit(c, t);
    s.length += ref ? h : 0.0;
    if (k > 0 && ref != previous) ++s.transitions;
    previous = ref;
    if (!clear_margin(c, t))
      ++s.ambiguous;
    else if (ref != covers(lit, t))
      ++s.mismatches;
  }
  return s;
}

// The distance from the piece end b to where spot_cone changes within ±window
// (bisection to rounding), or -1 if it doesn't change there beyond rounding: a
// tangent end (the piece is shorter than the window), or the end of a line
// lying on the cone's surface.
double end_error(const testing::ConeCase& c, double b, double window) {
  double lo = std::max(b - window, c.t0), hi = std::min(b + window, c.t1);
  const bool lit_lo = spot_lit(c, lo);
  if (lit_lo == spot_lit(c, hi) || !clear_margin(c, lo) || !clear_margin(c, hi)) return -1.0;
  for (int i = 0; i < 80 && hi - lo > 0.0; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    (spot_lit(c, mid) == lit_lo ? lo : hi) = mid;
  }
  return std::abs(b - 0.5 * (lo + hi));
}

// Structure: 0..2 ascending disjoint pieces of positive length within [t0, t1],
// two only for a cone wider than 90°.
void expect_well_formed(const testing::ConeCase& c, const ConeIntervals& lit, const std::string& where) {
  ASSERT_GE(lit.count, 0) << where;
  ASSERT_LE(lit.count, c.half_angle > std::numbers::pi / 2 ? 2 : 1) << where;
  for (int i = 0; i < lit.count; ++i) {
    EXPECT_LE(c.t0, lit.piece[i].x) << where;
    EXPECT_LT(lit.piece[i].x, lit.piece[i].y) << where;
    EXPECT_LE(lit.piece[i].y, c.t1) << where;
  }
  if (lit.count == 2) {
    EXPECT_LT(lit.piece[0].y, lit.piece[1].x) << where;
  }
}

// The worst results of one kind of case.
struct Worst {
  int cases = 0, ends = 0, unbracketed = 0;
  double end = 0.0;     // |end - where spot_cone changes| · crossing sine / scale
  double length = 0.0;  // |lit length - sampled lit length| / sample spacing,
                        // beyond the samples whose verdict is within rounding
};

// Bisects spot_cone's change next to each piece end (within ±1e-6 of the
// segment) and checks the distance, conditioned: rounding that moves the
// geometry by δ moves a crossing by δ/sin(crossing angle).
void check_ends(const testing::ConeCase& c, const ConeIntervals& lit, Worst& w, const std::string& where) {
  for (int p = 0; p < lit.count; ++p)
    for (double b : {lit.piece[p].x, lit.piece[p].y}) {
      if (b == c.t0 || b == c.t1) continue;
      const double e = end_error(c, b, 1e-6 * (c.t1 - c.t0));
      if (e < 0.0) {
        ++w.unbracketed;
        continue;
      }
      ++w.ends;
      const double normalized = e * testing::crossing_sine(c, b) / testing::scale(c);
      w.end = std::max(w.end, normalized);
      // Double rounding: a few 1e-16, more at the apex, where the reference's
      // own sample positions origin + t·dir round; 1e-12 leaves room for both.
      EXPECT_LE(normalized, 1e-12) << where << " end " << b << " error " << e;
    }
}

TEST(ConeIntervals, MatchBruteForceSamplingOfSpotCone) {
  // 4000 samples per case, each tested with spot_cone (edge 0) itself. Every
  // sample whose verdict is beyond rounding must agree with the pieces; the
  // lit length may differ by one sample spacing per transition (the samples
  // locate a boundary only to a spacing) and per sample within rounding; and
  // next to each piece end spot_cone must change (check_ends).
  constexpr int samples = 4000;
  const std::vector<testing::ConeCase> cases = testing::ConeCaseMaker(11).make(9 * 800);
  std::map<std::string, Worst> worst;
  int failures = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const testing::ConeCase& c = cases[i];
    const ConeIntervals lit = c.clip();
    const std::string where = c.kind + " case " + std::to_string(i);
    expect_well_formed(c, lit, where);
    const Sampled s = sample(c, lit, samples);
    const double h = (c.t1 - c.t0) / samples;
    const double length_error = std::abs(covered_length(lit) - s.length);
    const int allowed = std::max(s.transitions, 2 * lit.count) + s.ambiguous;
    if ((s.mismatches > 0 || length_error > allowed * h * (1 + 1e-9)) && ++failures <= 8)
      ADD_FAILURE() << where << ": " << s.mismatches << " mismatching samples, length error " << length_error / h
                    << " spacings";
    Worst& w = worst[c.kind];
    ++w.cases;
    w.length = std::max(w.length, length_error / h - s.ambiguous);
    check_ends(c, lit, w, where);
  }
  std::printf("%-24s %5s %5s %11s %10s %9s\n", "kind", "cases", "ends", "unbracketed", "end error", "length/h");
  for (const auto& [kind, w] : worst)
    std::printf("%-24s %5d %5d %11d %10.2e %9.2f\n", kind.c_str(), w.cases, w.ends, w.unbracketed, w.end, w.length);
}

}  // namespace
}  // namespace airlight::optics
