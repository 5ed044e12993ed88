#include "optics/light.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

namespace airlight::optics {
namespace {

glm::dvec3 spot_axis(const Light& light) { return glm::normalize(glm::dvec3(light.direction)); }

// Hermite smoothstep of t clamped to [0, 1].
double smoothstep01(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// Angle in [0, π] between `axis` and `v`: atan2(|a×v|, a·v) keeps it accurate
// near 0 and π and for a `v` that is unit only to rounding, where acos(a·v)
// loses digits.
double angle_between(const glm::dvec3& axis, const glm::dvec3& v) {
  return std::atan2(glm::length(glm::cross(axis, v)), glm::dot(axis, v));
}

// Parameters s where the line p + s·dir meets the double cone of half-angle
// `angle` around unit `axis` with its apex at the origin: sin²α (v·a)² = cos²α |v⊥|²,
// v = p + s·dir, v⊥ = v - (v·a)a, i.e. A s² + 2B s + C = 0. Eberly's form
// (v·a)² = cos²α |v|² has the coefficient (dir·a)² - cos²α, which cancels for
// narrow cones and near-axis lines; the v⊥ form keeps both terms small there.
// The discriminant B² - AC is expanded by hand: its sin⁴α terms cancel exactly,
// leaving cos²α (sin²α |da·p⊥ - pa·d⊥|² - cos²α |p⊥ × d⊥|²). Computed as
// B² - AC it would lose half its digits whenever the two roots are close
// compared with their distance from p — near α = 90°, where the two nappes
// merge into one plane, a line crosses both almost at once. Roots by the
// stable formula (Numerical Recipes §5.6). No thresholds: a negative
// discriminant (a line missing the cone, or a double root at the apex that
// rounding made complex) counts as 0, which keeps the apex; a missing root
// (A = 0: parallel to a generator) yields s = 0. Spurious roots only add
// harmless bounds.
std::array<double, 2> double_cone_roots(const glm::dvec3& p, const glm::dvec3& dir,
                                        const glm::dvec3& axis, double angle) {
  const double sn = std::sin(angle), cs = std::cos(angle);
  const double s2 = sn * sn, c2 = cs * cs;
  const double pa = glm::dot(p, axis), da = glm::dot(dir, axis);
  const glm::dvec3 p_perp = p - pa * axis, d_perp = dir - da * axis;
  const double A = s2 * da * da - c2 * glm::dot(d_perp, d_perp);
  const double B = s2 * pa * da - c2 * glm::dot(p_perp, d_perp);
  const double C = s2 * pa * pa - c2 * glm::dot(p_perp, p_perp);
  const glm::dvec3 e = da * p_perp - pa * d_perp, m = glm::cross(p_perp, d_perp);
  const double disc = c2 * (s2 * glm::dot(e, e) - c2 * glm::dot(m, m));
  const double q = -(B + std::copysign(std::sqrt(std::max(disc, 0.0)), B));
  return {A != 0.0 ? q / A : 0.0, q != 0.0 ? C / q : 0.0};
}

bool inside_unit_square(const glm::dvec2& uv) {
  return uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0;
}

bool has_gobo(const Light& light) { return light.gobo && !light.gobo->empty(); }

// The gobo's colour at uv: black outside the unit square (docs/design.md §1).
glm::dvec3 gobo_color(const Image& gobo, const glm::dvec2& uv) {
  return inside_unit_square(uv) ? sample_gobo(gobo, uv) : glm::dvec3(0.0);
}

// A spot's light map toward unit `dir` from it: cone factor · gobo colour.
glm::dvec3 spot_map(const Light& light, const glm::dvec3& dir) {
  const double cone = spot_cone(light, dir);
  if (cone == 0.0 || !has_gobo(light)) return glm::dvec3(cone);
  return cone * gobo_color(*light.gobo, gobo_uv(light, dir));
}

// x − beam.origin in the beam's frame: (along right, along up, along the axis).
glm::dvec3 beam_coordinates(const Light& light, const glm::dvec3& x) {
  glm::dvec3 right, up;
  gobo_frame(light, right, up);
  const glm::dvec3 d = x - glm::dvec3(light.beam->origin);
  return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, spot_axis(light))};
}

// beam_uv of a point with beam coordinates p.
glm::dvec2 across(const Beam& beam, const glm::dvec3& p) {
  return glm::dvec2(0.5) + glm::dvec2(p) / glm::dvec2(beam.size);
}

// A beam's light map at x: inside the box, the gobo colour across the aperture.
glm::dvec3 beam_map(const Light& light, const glm::dvec3& x) {
  if (!inside_beam(light, x)) return glm::dvec3(0.0);
  return has_gobo(light) ? gobo_color(*light.gobo, beam_uv(light, x)) : glm::dvec3(1.0);
}

}  // namespace

void gobo_frame(const Light& light, glm::dvec3& right, glm::dvec3& up) {
  const glm::dvec3 axis = spot_axis(light);
  glm::dvec3 side = glm::cross(axis, glm::dvec3(light.gobo_up));
  if (glm::dot(side, side) < 1e-24) side = glm::cross(axis, glm::dvec3(0, 0, 1));
  if (glm::dot(side, side) < 1e-24) side = glm::cross(axis, glm::dvec3(1, 0, 0));
  right = glm::normalize(side);
  up = glm::cross(right, axis);
}

double spot_cone(const Light& light, const glm::dvec3& dir) {
  const double angle = angle_between(spot_axis(light), dir);
  const double cone = radians(light.cone_deg);
  const double edge = radians(light.edge_deg);
  if (edge <= 0.0) return angle <= cone ? 1.0 : 0.0;  // Nilsson eq. 2.9: hard cut
  return smoothstep01((cone - angle) / edge);          // 1 at cone - edge, 0 at cone
}

ConeIntervals cone_intervals(const glm::dvec3& apex, const glm::dvec3& axis, double half_angle,
                             const glm::dvec3& origin, const glm::dvec3& dir, double t0, double t1) {
  ConeIntervals lit;
  if (!(t1 > t0)) return lit;
  // Roots about the foot of the perpendicular from the apex, so that their
  // rounding scales with the line's distance from the apex, not the origin's.
  const glm::dvec3 w = origin - apex;
  const double foot = -glm::dot(w, dir);
  const std::array<double, 2> s = double_cone_roots(w + foot * dir, dir, axis, half_angle);
  const double r0 = std::clamp(foot + s[0], t0, t1), r1 = std::clamp(foot + s[1], t0, t1);
  const std::array<double, 4> bounds{t0, std::min(r0, r1), std::max(r0, r1), t1};
  // The lit set's boundary (angle = α, or the apex) lies on the double cone, so
  // between consecutive bounds the angle never crosses α: each piece is lit or
  // dark as a whole, and its midpoint tells which. That picks the nappe and
  // covers α >= π/2 without case analysis.
  for (int k = 0; k < 3; ++k) {
    const double a = bounds[k], b = bounds[k + 1];
    if (!(b > a) || angle_between(axis, w + 0.5 * (a + b) * dir) > half_angle) continue;
    if (lit.count > 0 && lit.piece[lit.count - 1].y == a)
      lit.piece[lit.count - 1].y = b;  // continues the previous piece across a spurious bound
    else
      lit.piece[lit.count++] = {a, b};  // at most lit, dark, lit: two pieces
  }
  return lit;
}

glm::dvec2 gobo_uv(const Light& light, const glm::dvec3& dir) {
  const glm::dvec2 outside(-1.0);
  const double cone = radians(light.cone_deg);
  if (cone >= 0.5 * std::numbers::pi) return outside;
  glm::dvec3 right, up;
  gobo_frame(light, right, up);
  const double z = glm::dot(dir, spot_axis(light));
  if (z <= 0.0) return outside;
  const double scale = 0.5 / (z * std::tan(cone));
  return {0.5 + glm::dot(dir, right) * scale, 0.5 + glm::dot(dir, up) * scale};
}

glm::dvec3 sample_gobo(const Image& gobo, const glm::dvec2& uv) {
  // Pixel centres sit at (i + 0.5)/W; row 0 is the top (v = 1).
  const double px = uv.x * gobo.width - 0.5;
  const double py = (1.0 - uv.y) * gobo.height - 0.5;
  const double fx = std::floor(px), fy = std::floor(py);
  const double wx = px - fx, wy = py - fy;
  auto texel = [&](double x, double y) {
    const int ix = std::clamp(static_cast<int>(x), 0, gobo.width - 1);
    const int iy = std::clamp(static_cast<int>(y), 0, gobo.height - 1);
    return glm::dvec3(gobo.at(ix, iy));
  };
  const glm::dvec3 top = glm::mix(texel(fx, fy), texel(fx + 1, fy), wx);
  const glm::dvec3 bottom = glm::mix(texel(fx, fy + 1), texel(fx + 1, fy + 1), wx);
  return glm::mix(top, bottom, wy);
}

glm::dvec2 beam_uv(const Light& light, const glm::dvec3& x) {
  return across(*light.beam, beam_coordinates(light, x));
}

double beam_depth(const Light& light, const glm::dvec3& x) {
  return glm::dot(x - glm::dvec3(light.beam->origin), spot_axis(light));
}

bool inside_beam(const Light& light, const glm::dvec3& x) {
  const glm::dvec3 p = beam_coordinates(light, x);
  return inside_unit_square(across(*light.beam, p)) && p.z >= 0.0 && p.z <= light.beam->length;
}

Interval beam_interval(const Light& light, const glm::dvec3& origin, const glm::dvec3& dir, double t0,
                       double t1) {
  glm::dvec3 right, up;
  gobo_frame(light, right, up);
  const glm::dvec3 d(glm::dot(dir, right), glm::dot(dir, up), glm::dot(dir, spot_axis(light)));
  const Beam& beam = *light.beam;
  const glm::dvec3 half(0.5 * beam.size.x, 0.5 * beam.size.y, 0.0);
  return slab_overlap(beam_coordinates(light, origin), d, -half, half + glm::dvec3(0, 0, beam.length), t0, t1);
}

glm::dvec3 light_map(const Light& light, const glm::dvec3& x) {
  switch (light.type) {
    case LightType::point: break;
    case LightType::spot: {
      const glm::dvec3 delta = x - glm::dvec3(light.position);
      const double r = glm::length(delta);
      return spot_map(light, r > 0.0 ? delta / r : spot_axis(light));  // at the light: arrival's axis
    }
    case LightType::directional:
      if (has_beam(light)) return beam_map(light, x);
      break;
  }
  return glm::dvec3(1.0);
}

glm::dvec3 radiant_intensity(const Light& light, const glm::dvec3& dir) {
  switch (light.type) {
    case LightType::point: return glm::dvec3(light.intensity);
    case LightType::spot: return glm::dvec3(light.intensity) * spot_map(light, dir);
    case LightType::directional: return glm::dvec3(light.irradiance);
  }
  return glm::dvec3(0.0);
}

Arrival arrival(const Light& light, const LightModel& model, const glm::dvec3& x) {
  Arrival a;
  if (light.type == LightType::directional) {
    a.irradiance = glm::dvec3(light.irradiance) * light_map(light, x);
    a.to_light = -glm::normalize(glm::dvec3(light.direction));
    a.distance = std::numeric_limits<double>::infinity();
    return a;
  }
  const glm::dvec3 delta = glm::dvec3(light.position) - x;
  a.distance = glm::length(delta);
  a.to_light = a.distance > 0.0 ? delta / a.distance : spot_axis(light) * -1.0;
  const glm::dvec3 intensity = radiant_intensity(light, -a.to_light);
  const double r = std::max(a.distance, min_light_distance);
  const double falloff = model.type == LightModelType::simplified
                             ? double(model.a1) * r * r + double(model.a0)  // Nilsson eq. 2.13
                             : r * r;
  a.irradiance = intensity / falloff;
  return a;
}

}  // namespace airlight::optics
