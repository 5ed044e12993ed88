#pragma once
// Random line–cone configurations shared by the tests of cone_intervals
// (light.hpp): the C++ against brute-force sampling (light_test.cpp) and its GLSL
// twin against the C++ (src/methods/kit/testing/twins/cone_twin_test.cpp). Each kind is a way the
// clipping can go wrong: a generic line, the apex behind the eye, a line along
// the axis, through the apex, a wide cone (>= 90°), a line parallel to a
// generator (or on the surface), tangent to the cone, a narrow cone, a line
// starting at the apex.
#include <airlight/scene.hpp>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "optics/light.hpp"

namespace airlight::optics::testing {

struct ConeCase {
  std::string kind;
  Light spot;  // hard cut (Nilsson eq. 2.9): spot_cone is 1 exactly on the lit set
  glm::dvec3 apex{0.0}, axis{0, 0, 1};  // the spot's cone, converted as spot_cone does
  double half_angle = 0.0;
  glm::dvec3 origin{0.0}, dir{1, 0, 0};  // dir unit
  double t0 = 0.0, t1 = 1.0;

  ConeIntervals clip() const { return cone_intervals(apex, axis, half_angle, origin, dir, t0, t1); }
};

// The angle in [0, π] between the axis and x - apex at x = origin + t·dir, as
// spot_cone measures it.
inline double angle_off_axis(const ConeCase& c, double t) {
  const glm::dvec3 v = c.origin + t * c.dir - c.apex;
  return std::atan2(glm::length(glm::cross(c.axis, v)), glm::dot(c.axis, v));
}

// The size of the geometry, which rounding errors of positions scale with.
inline double scale(const ConeCase& c) {
  return glm::length(c.origin - c.apex) + std::max(std::abs(c.t0), std::abs(c.t1));
}

// |sin| of the angle between the line and the cone's surface at the point t of
// the line on it: rounding that moves the line by δ moves the crossing by
// δ/sin. The surface's normal at v = x - apex is the unit vector in the plane of
// the axis and v, perpendicular to v. Within 1e-6 of the apex (where rounding
// leaves v's direction unknown, and the normal undefined) the line crosses the
// generators along itself: |sin(ψ ∓ α)|, ψ its angle from the axis.
inline double crossing_sine(const ConeCase& c, double t) {
  const glm::dvec3 v = c.origin + t * c.dir - c.apex, a = c.axis;
  const double length = glm::length(v);
  if (length <= 1e-6 * scale(c)) {
    const double psi = std::atan2(glm::length(glm::cross(a, c.dir)), glm::dot(a, c.dir));
    return std::min(std::abs(std::sin(psi - c.half_angle)), std::abs(std::sin(psi + c.half_angle)));
  }
  const glm::dvec3 u = v / length, normal = a - glm::dot(a, u) * u;
  const double n = glm::length(normal);
  return n > 0.0 ? std::abs(glm::dot(c.dir, normal / n)) : 1.0;
}

// Random cases of each kind. Every random draw is its own statement: the order
// in which C++ evaluates function arguments or operands is unspecified, and the
// cases must not depend on the compiler. The spot's float values are drawn as
// floats, never rounded from doubles: GCC 12.2 at -O2 and above (SLP
// vectorizer) was seen to fold double(float(x)) into x for a pair of
// components, which left the spot and its double twin 1e-8 apart.
class ConeCaseMaker {
public:
  explicit ConeCaseMaker(unsigned seed) : rng_(seed) {}

  // count cases, the kinds in turn.
  std::vector<ConeCase> make(int count) {
    using Kind = void (ConeCaseMaker::*)(ConeCase&);
    static constexpr std::array<std::pair<const char*, Kind>, 9> kinds{{
        {"generic", &ConeCaseMaker::generic},           {"apex behind the eye", &ConeCaseMaker::apex_behind},
        {"along the axis", &ConeCaseMaker::along_axis}, {"through the apex", &ConeCaseMaker::through_apex},
        {"wide cone", &ConeCaseMaker::wide},            {"parallel to a generator", &ConeCaseMaker::generator},
        {"tangent", &ConeCaseMaker::tangent},           {"narrow cone", &ConeCaseMaker::narrow},
        {"from the apex", &ConeCaseMaker::from_apex},
    }};
    std::vector<ConeCase> cases;
    for (int i = 0; i < count; ++i) {
      const auto& [name, kind] = kinds[i % kinds.size()];
      ConeCase c = random_cone(name);
      (this->*kind)(c);
      cases.push_back(c);
    }
    return cases;
  }

private:
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  double sign() { return uniform(0, 1) < 0.5 ? -1.0 : 1.0; }
  bool coin() { return sign() > 0.0; }
  glm::dvec3 unit() {
    std::normal_distribution<double> n;
    for (;;) {
      const glm::dvec3 v{n(rng_), n(rng_), n(rng_)};  // braces: evaluated in order
      if (glm::dot(v, v) > 1e-6) return glm::normalize(v);
    }
  }
  glm::dvec3 box() { return {uniform(-5, 5), uniform(-5, 5), uniform(-5, 5)}; }
  float uniform_float(float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng_); }
  glm::vec3 box_float() { return {uniform_float(-5, 5), uniform_float(-5, 5), uniform_float(-5, 5)}; }
  glm::vec3 unit_float() {
    std::normal_distribution<float> n;
    for (;;) {
      const glm::vec3 v{n(rng_), n(rng_), n(rng_)};
      if (glm::dot(v, v) > 1e-6f) return glm::normalize(v);
    }
  }
  glm::dvec3 perpendicular(const glm::dvec3& a) { return glm::normalize(glm::cross(a, unit())); }
  // The unit generator at azimuth `u` (unit, ⊥ axis) of the case's cone.
  static glm::dvec3 generator_dir(const ConeCase& c, const glm::dvec3& u) {
    return std::cos(c.half_angle) * c.axis + std::sin(c.half_angle) * u;
  }

  // The spot's hard cone, and the double values spot_cone makes of it.
  static void set_cone(ConeCase& c, const glm::vec3& apex, const glm::vec3& axis, float cone_deg) {
    c.spot.type = LightType::spot;
    c.spot.position = apex;
    c.spot.direction = axis;
    c.spot.cone_deg = cone_deg;
    c.spot.edge_deg = 0.0f;
    c.apex = glm::dvec3(apex);
    c.axis = glm::normalize(glm::dvec3(axis));
    c.half_angle = cone_deg * std::numbers::pi / 180.0;
  }
  static void set_cone_deg(ConeCase& c, float cone_deg) { set_cone(c, c.spot.position, c.spot.direction, cone_deg); }
  static void start_at(ConeCase& c, double t0) {  // keeps the segment's length
    c.t1 += t0 - c.t0;
    c.t0 = t0;
  }

  // Any cone, a random line; the segment starts at 0 or near it and is 1 cm to 30 m long.
  ConeCase random_cone(const char* kind) {
    ConeCase c;
    c.kind = kind;
    const glm::vec3 apex = box_float(), axis = unit_float();
    set_cone(c, apex, axis, uniform_float(0.5f, 179.5f));
    c.origin = box();
    c.dir = unit();
    c.t0 = coin() ? 0.0 : uniform(-3, 1);
    c.t1 = c.t0 + log_uniform(0.01, 30);
    return c;
  }

  void generic(ConeCase&) {}
  void apex_behind(ConeCase& c) {  // the apex at t = -0.05 .. -5, up to 0.5 off the line
    const double behind = uniform(0.05, 5), off = uniform(0, 0.5);
    c.origin = c.apex + behind * c.dir + off * perpendicular(c.dir);
    start_at(c, 0.0);
  }
  void along_axis(ConeCase& c) {  // on the axis line, or up to 0.1 beside it
    c.dir = sign() * c.axis;
    c.origin = c.apex + uniform(-5, 5) * c.axis;
    if (coin()) {
      const double off = log_uniform(1e-6, 0.1);
      c.origin += off * perpendicular(c.axis);
    }
  }
  void through_apex(ConeCase& c) {  // the apex at t = -2 .. 8; half the lines near a generator
    if (coin()) {
      const glm::dvec3 g = generator_dir(c, perpendicular(c.axis));
      const double off = sign() * log_uniform(1e-9, 1e-2);
      c.dir = glm::normalize(g + off * unit());
    }
    c.origin = c.apex - uniform(-2, 8) * c.dir;
  }
  void wide(ConeCase& c) {  // 90° (a half-space) to 180° (everything); lines through the dark backward cone
    const float random_wide = uniform_float(90.0f, 180.0f);
    const float cones[] = {90.0f, 90.5f, random_wide, 179.9f, 180.0f};
    set_cone_deg(c, cones[std::uniform_int_distribution<int>(0, 4)(rng_)]);
    const double behind = uniform(0.1, 5), off = uniform(0, 0.5);
    const glm::dvec3 target = c.apex - behind * c.axis + off * unit();
    if (coin()) c.dir = glm::normalize(target - c.origin);
  }
  void generator(ConeCase& c) {  // A = 0: parallel to a generator, or on the surface itself
    c.dir = sign() * generator_dir(c, perpendicular(c.axis));
    if (coin())
      c.origin = c.apex + uniform(-3, 3) * c.dir;
    else
      c.origin = c.apex + uniform(-2, 2) * unit();
  }
  void tangent(ConeCase& c) {
    // In the tangent plane at x = apex + r·g (spanned by g and the azimuthal
    // e), moved off the surface along its normal n by 0 or ±1e-9 .. 1e-3.
    const glm::dvec3 a = c.axis, u = perpendicular(a), g = generator_dir(c, u);
    const glm::dvec3 e = glm::cross(a, u), n = glm::normalize(glm::cross(e, g));
    const double beta = uniform(0, std::numbers::pi);
    c.dir = std::cos(beta) * g + std::sin(beta) * e;
    const double offset = coin() ? 0.0 : sign() * log_uniform(1e-9, 1e-3);
    const double r = uniform(0.2, 5), back = uniform(-1, 6);
    c.origin = c.apex + r * g + offset * n - back * c.dir;
  }
  void narrow(ConeCase& c) {  // 0.01° .. 2°, lines aimed at the axis
    set_cone_deg(c, std::exp(uniform_float(std::log(0.01f), std::log(2.0f))));
    const double along = uniform(0, 10), off = log_uniform(1e-4, 1);
    const glm::dvec3 target = c.apex + along * c.axis + off * unit();
    c.dir = glm::normalize(target - c.origin);
  }
  void from_apex(ConeCase& c) {  // along the axis, against it or anywhere
    c.origin = c.apex;
    const int which = std::uniform_int_distribution<int>(0, 2)(rng_);
    if (which < 2) c.dir = (which == 0 ? 1.0 : -1.0) * c.axis;
    start_at(c, uniform(-3, 0));
  }

  std::mt19937 rng_;
};

}  // namespace airlight::optics::testing
