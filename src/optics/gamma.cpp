#include "optics/gamma.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

#include "optics/closed_form.hpp"
#include "optics/light.hpp"
#include "optics/phase.hpp"

namespace airlight::optics {
namespace {

constexpr double pi = std::numbers::pi;

// ---- Biri 2006's angular formulation ------------------------------------------
// With the foot of the perpendicular from the light at x = xs, distance h, Biri
// writes x - xs = h·tan φ (exact): dx/r² = dφ/h, cos θ = -sin φ. We integrate
// in s = gd⁻¹(φ) = asinh((x - xs)/h) instead of his degree-4 polynomial in φ
// (off by percents to orders of magnitude near ±π/2; docs/decisions.md, Numerics): tan φ =
// sinh s, r = h·cosh s, dφ = ds/cosh s, x + r = xs + h·e^s, cos θ = -tanh s.
// Forward and backward phase peaks at φ → ∓π/2 become O(1)-wide features at
// s ≈ ±ln(2/width), and the integrand is analytic and bounded in the strip
// |Im s| < π/2, so Gauss–Legendre panels of length <= 2 in s converge
// geometrically. Panels are also cut where σt·(x + r) grows by 4 (thick media
// put the mass in a thin layer at the near end), and the tail beyond a growth
// of 32 is dropped (< e^-32 times the phase's max/min ratio, ~4e6: < 1e-7).

// 8-point Gauss–Legendre on [-1, 1]: positive abscissae and weights.
constexpr std::array<double, 4> gl_x = {0.960289856497536231684, 0.796666477413626739592,
                                        0.525532409916328985818, 0.183434642495649804939};
constexpr std::array<double, 4> gl_w = {0.101228536290376259153, 0.222381034453374470544,
                                        0.313706645877887287338, 0.362683783378361982965};
constexpr double max_panel = 2.0;      // in s
constexpr double panel_growth = 4.0;   // of σt·(x + r) per panel
constexpr double tail_growth = 32.0;   // beyond it the rest is dropped
constexpr int max_panels = 64;         // > 2·ln(2·length/1 µm)/2 + 32/4 for lengths up to 1e8 m

// asinh without the cancellation of log(z + sqrt(z² + 1)) for z < 0.
double stable_asinh(double z) {
  const double a = std::abs(z);
  return std::copysign(std::log1p(a + a * a / (1.0 + std::sqrt(1.0 + a * a))), z);
}

// The view segment [t0, t1] relative to a point or spot light.
struct Foot {
  double xs = 0.0, h = 0.0;  // foot of the perpendicular, distance to the line (>= ε)
  glm::dvec3 normal{0.0};    // unit, from the foot toward the light
};

Foot foot_of(const Ray& ray, const glm::dvec3& light) {
  const glm::dvec3 delta = light - ray.origin;
  Foot f;
  f.xs = glm::dot(delta, ray.dir);
  const glm::dvec3 off = delta - f.xs * ray.dir;  // Nilsson eq. 2.16 as |Δ - zs·Ω| (docs/decisions.md, Numerics)
  const double h = glm::length(off);
  f.normal = h > 0.0 ? off / h : glm::normalize(glm::cross(ray.dir, glm::dvec3(ray.dir.y, ray.dir.z, -ray.dir.x)));
  // Within 1 µm of the line the light is moved 1 µm off it (min_light_distance):
  // finite, as the quadrature's clamp of r (they differ only there).
  f.h = std::max(h, min_light_distance);
  return f;
}

// The light's angular factor at s: phase · spot cone (1 for point lights),
// and under the simplified model its falloff over the physical one's,
// r²/(a1·r² + a0) (Nilsson eq. 2.13), r = h·cosh s.
double angular_factor(const Phase& phase_fn, const LightModel& model, const Light& light, const Ray& ray,
                      const Foot& f, double s) {
  double factor = phase(phase_fn, -std::tanh(s));
  if (model.type == LightModelType::simplified) {
    const double r2 = f.h * f.h * std::cosh(s) * std::cosh(s);
    factor *= r2 / (double(model.a1) * r2 + double(model.a0));
  }
  if (light.type != LightType::spot || light.edge_deg <= 0.0f) return factor;
  const glm::dvec3 from_light = std::tanh(s) * ray.dir - f.normal / std::cosh(s);
  return factor * spot_cone(light, glm::normalize(from_light));
}

// ∫_{t0}^{t1} p(cos θ)·cone·exp(-σt(x + r))/r² dx per channel, by the panels
// above; under the simplified model (σt = 0, isotropic p) 1/(a1·r² + a0) for 1/r².
glm::dvec3 biri_angular(const Phase& phase_fn, const LightModel& model, const glm::dvec3& sigma_t, const Light& light,
                        const Ray& ray, double t0, double t1) {
  const Foot f = foot_of(ray, glm::dvec3(light.position));
  const double s0 = stable_asinh((t0 - f.xs) / f.h), s1 = stable_asinh((t1 - f.xs) / f.h);
  const double fast = std::max({sigma_t.x, sigma_t.y, sigma_t.z});
  const double slow = std::min({sigma_t.x, sigma_t.y, sigma_t.z});
  const double e0 = f.h * std::exp(s0);  // x + r - xs at t0
  glm::dvec3 sum(0.0);
  double a = s0;
  for (int panel = 0; panel < max_panels && a < s1; ++panel) {
    const double b = std::min({s1, a + max_panel, a + std::log1p(panel_growth / (fast * f.h * std::exp(a)))});
    for (int i = 0; i < 8; ++i) {
      const double s = 0.5 * (a + b) + 0.5 * (b - a) * (i < 4 ? -gl_x[i] : gl_x[i - 4]);
      const double w = 0.5 * (b - a) * gl_w[i % 4];
      const double growth = e0 * std::expm1(s - s0);  // (x + r) - (x + r)(t0), no cancellation
      sum += w * angular_factor(phase_fn, model, light, ray, f, s) / std::cosh(s) * glm::exp(-sigma_t * growth);
    }
    if (slow * e0 * std::expm1(b - s0) > tail_growth) break;
    a = b;
  }
  const double r_t0 = glm::length(glm::dvec3(light.position) - (ray.origin + t0 * ray.dir));
  return sum * glm::exp(-sigma_t * (t0 + r_t0)) / f.h;
}

// ---- point and spot lights over one lit piece [a, b] --------------------------

bool isotropic(const Phase& phase_fn) {
  return std::all_of(phase_fn.lobes.begin(), phase_fn.lobes.end(),
                     [](const PhaseLobe& l) { return l.type == PhaseType::isotropic; });
}

// Sun et al. (Kingston eqs. 36-40) from the piece's start, times the eye's
// extinction up to it.
glm::dvec3 sun_piece(const Medium& medium, const Light& light, const Ray& ray, double a, double b) {
  const glm::dvec3 start = ray.origin + a * ray.dir, position(light.position);
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c) {
    const double sigma_t = medium.sigma_t()[c];
    out[c] = std::exp(-sigma_t * a) *
             sun_airlight(medium.sigma_s[c], sigma_t, light.intensity[c], start, ray.dir, position, b - a);
  }
  return out;
}

glm::dvec3 nilsson_piece(const Medium& medium, const LightModel& model, const Light& light, const Ray& ray,
                         double a, double b) {
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c)
    out[c] = nilsson_airlight(medium.sigma_s[c], light.intensity[c], model.a0, model.a1, ray.origin, ray.dir,
                              glm::dvec3(light.position), a, b);
  return out;
}

// One lit piece [a, b] of a point or spot light; 0 if empty.
glm::dvec3 local_piece(const Medium& medium, const LightModel& model, const Light& light, const Ray& ray,
                       double a, double b) {
  if (!(b > a)) return glm::dvec3(0.0);
  const bool smooth_edge = light.type == LightType::spot && light.edge_deg > 0.0f;
  const glm::dvec3 sigma_s(medium.sigma_s), intensity(light.intensity);
  if (model.type == LightModelType::simplified) {  // isotropic, T = 1 (Nilsson 2.5); the edge has no closed form
    if (!smooth_edge) return nilsson_piece(medium, model, light, ray, a, b);
    return sigma_s * intensity * biri_angular(Phase{}, model, glm::dvec3(0.0), light, ray, a, b);
  }
  if (isotropic(medium.phase) && !smooth_edge) return sun_piece(medium, light, ray, a, b);
  return sigma_s * intensity * biri_angular(medium.phase, model, glm::dvec3(medium.sigma_t()), light, ray, a, b);
}

// A spot over the pieces of [t0, t1] its cone lights (hard cut at cone_deg,
// Nilsson eq. 2.9), each cut again at the inner cone's ends under a smooth
// edge (the cone factor has kinks there); those lie inside, in ascending order.
glm::dvec3 spot_gamma(const Medium& medium, const LightModel& model, const Light& light, const Ray& ray, double t0,
                      double t1) {
  const glm::dvec3 apex(light.position), axis = glm::normalize(glm::dvec3(light.direction));
  const double cone = light.cone_deg * pi / 180.0, inner = cone - light.edge_deg * pi / 180.0;
  const bool cut = light.edge_deg > 0.0f && inner > 0.0;
  const ConeIntervals lit = cone_intervals(apex, axis, cone, ray.origin, ray.dir, t0, t1);
  glm::dvec3 sum(0.0);
  for (int k = 0; k < lit.count; ++k) {
    double start = lit.piece[k].x;
    const double end = lit.piece[k].y;
    const ConeIntervals core = cut ? cone_intervals(apex, axis, inner, ray.origin, ray.dir, start, end) : ConeIntervals{};
    for (int j = 0; j < core.count; ++j) {
      sum += local_piece(medium, model, light, ray, start, core.piece[j].x) +
             local_piece(medium, model, light, ray, core.piece[j].x, core.piece[j].y);
      start = core.piece[j].y;
    }
    sum += local_piece(medium, model, light, ray, start, end);
  }
  return sum;
}

// ---- directional lights --------------------------------------------------------

// ∫_0^L exp(-k t) dt by expm1, exact as k → 0.
double exponential_length(double k, double L) { return k == 0.0 ? L : -std::expm1(-k * L) / k; }

// A directional light: σs·p·E·∫ exp(-σt(t + s(t))) dt with s(t) the distance
// back to a beam's aperture, s(t) = s(0) + (dir·axis)·t (linear: exact), or no
// light leg for an unbounded sun (docs/design.md §1). Under the simplified model T = 1
// and the phase is isotropic (Nilsson 2.5).
glm::dvec3 directional(const Medium& medium, const LightModel& model, const Light& light, const Ray& ray,
                       double t0, double t1) {
  const glm::dvec3 travel = glm::normalize(glm::dvec3(light.direction));
  const bool simplified = model.type == LightModelType::simplified;
  const double p = simplified ? 1.0 / (4.0 * pi) : phase(medium.phase, glm::dot(-travel, ray.dir));
  double along = 0.0, s_start = 0.0;  // light-leg growth per unit t, and its value at t0
  if (has_beam(light)) {
    const Interval inside = beam_interval(light, ray.origin, ray.dir, t0, t1);
    if (inside.empty()) return glm::dvec3(0.0);
    t0 = inside.lo;
    t1 = inside.hi;
    along = glm::dot(ray.dir, travel);
    s_start = std::max(beam_depth(light, ray.origin + t0 * ray.dir), 0.0);
  }
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c) {
    const double sigma_t = simplified ? 0.0 : medium.sigma_t()[c];
    out[c] = medium.sigma_s[c] * p * light.irradiance[c] * std::exp(-sigma_t * (t0 + s_start)) *
             exponential_length(sigma_t * (1.0 + along), t1 - t0);
  }
  return out;
}

}  // namespace

glm::dvec3 gamma(const Medium& medium, const LightModel& model, const Light& light, const Ray& ray, double t0,
                 double t1) {
  if (!(t1 > t0)) return glm::dvec3(0.0);
  if (light.type == LightType::directional) return directional(medium, model, light, ray, t0, t1);
  if (light.type == LightType::point) return local_piece(medium, model, light, ray, t0, t1);
  return spot_gamma(medium, model, light, ray, t0, t1);
}

float SunTable::F(float u, float v) const {
  if (!(v > 0.0f)) return 0.0f;
  const float w = v < float(pi / 2) ? std::tan(v) : std::numeric_limits<float>::infinity();
  return F_tan(u, w, std::min(v, float(pi / 2)));
}

// The grid's bilinear R at (ln u, ln tan v), clamped to the grid (R → 1 or its
// v = π/2 limit beyond it, within 1e-4: see build_sun_table).
float SunTable::F_tan(float u, float tan_v, float v) const {
  if (!(v > 0.0f)) return 0.0f;
  const float px = std::clamp((std::log(u) - sun_table_log_u_min) / sun_table_log_u_step, 0.0f, float(width - 1));
  const float py = std::clamp((std::log(tan_v) - sun_table_log_tan_min) / sun_table_log_tan_step, 0.0f,
                              float(height - 1));
  const int i = std::min(int(px), width - 2), j = std::min(int(py), height - 2);
  const float fx = px - float(i), fy = py - float(j);
  auto at = [&](int di, int dj) { return texels[size_t(j + dj) * size_t(width) + size_t(i + di)]; };
  const float r = (at(0, 0) * (1.0f - fx) + at(1, 0) * fx) * (1.0f - fy) + (at(0, 1) * (1.0f - fx) + at(1, 1) * fx) * fy;
  return r * sun_asymptote(u, v);
}

float sun_asymptote(float u, float v) {
  const float z = u * v;
  const float q = z < 1e-2f ? 1.0f - z * (0.5f - z * (1.0f / 6.0f - z / 24.0f)) : (1.0f - std::exp(-z)) / z;
  return v * q;
}

SunTable build_sun_table() {
  SunTable t;
  t.width = sun_table_width;
  t.height = sun_table_height;
  t.texels.resize(size_t(t.width) * size_t(t.height));
  // In s = ln tan ξ: F = ∫ exp(-u e^s)/(2 cosh s) ds, summed cell by cell with
  // 8-point Gauss–Legendre (cells of 0.06 in s: exact to rounding), from F at
  // the first row by the adaptive rule.
  for (int i = 0; i < t.width; ++i) {
    const double u = std::exp(sun_table_log_u_min + i * double(sun_table_log_u_step));
    auto v_of = [](int j) { return std::atan(std::exp(sun_table_log_tan_min + j * double(sun_table_log_tan_step))); };
    double F = sun_F(u, v_of(0));
    for (int j = 0; j < t.height; ++j) {
      if (j > 0) {
        const double a = sun_table_log_tan_min + (j - 1) * double(sun_table_log_tan_step);
        const double b = a + sun_table_log_tan_step;
        for (int k = 0; k < 8; ++k) {
          const double s = 0.5 * (a + b) + 0.5 * (b - a) * (k < 4 ? -gl_x[k] : gl_x[k - 4]);
          F += 0.5 * (b - a) * gl_w[k % 4] * std::exp(-u * std::exp(s)) / (2.0 * std::cosh(s));
        }
      }
      const double v = v_of(j), z = u * v;
      t.texels[size_t(j) * size_t(t.width) + size_t(i)] = float(F / (v * -std::expm1(-z) / z));
    }
  }
  return t;
}

namespace {

// tan ξ at offset e from the foot, distance r from the light (sun.glsl's
// sun_tan_xi): (e + r)/r0, as r0/(r - e) for e < 0 where e + r cancels.
float tan_xi(float e, float r0, float r) { return e >= 0.0f ? (e + r) / r0 : r0 / (r - e); }

}  // namespace

double sun_airlight_table(const SunTable& table, double sigma_s, double sigma_t, double I0, const glm::dvec3& origin,
                          const glm::dvec3& dir, const glm::dvec3& light, double d) {
  const glm::vec3 delta(light - origin), unit(dir);
  const float xs = glm::dot(delta, unit);
  const float r0 = std::max(glm::length(delta - xs * unit), float(min_light_distance));
  const float d_lv = std::hypot(xs, r0), r_d = std::hypot(float(d) - xs, r0);
  const float w0 = tan_xi(-xs, r0, d_lv), w1 = tan_xi(float(d) - xs, r0, r_d);
  const float u = float(sigma_t) * r0;
  const float F0 = table.F_tan(u, w0, std::atan(w0)), F1 = table.F_tan(u, w1, std::atan(w1));
  // Kingston eq. 38 where the difference is well-conditioned, else the integral.
  if (!(d > 0.0) || -float(sigma_t) * xs > sun_table_max_gain || !(F1 + F0 <= sun_table_max_condition * (F1 - F0)))
    return sun_airlight(sigma_s, sigma_t, I0, origin, dir, light, d);
  return float(sigma_s) * float(I0) / (2.0f * float(pi) * r0) * std::exp(-float(sigma_t) * xs) * (F1 - F0);
}

}  // namespace airlight::optics
