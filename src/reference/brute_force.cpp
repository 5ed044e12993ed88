#include "reference/brute_force.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <limits>
#include <numbers>
#include <optional>
#include <tbb/parallel_for.h>

#include "geometry/camera.hpp"
#include "optics/gauss_kronrod.hpp"
#include "optics/light.hpp"
#include "optics/media.hpp"
#include "optics/phase.hpp"
#include "optics/slab.hpp"

namespace airlight::reference {
namespace {

using glm::dvec3;
constexpr double infinity = std::numeric_limits<double>::infinity();
// The reference's convention (reference.cpp): shadow rays to a point or spot
// light stop this fraction short of it, so a lamp on a ceiling is not blocked.
constexpr double light_clearance = 1e-5;
// Visibility changes are located to this fraction of the ray's length.
constexpr double boundary_resolution = 1e-9;

struct Triangle {
  dvec3 p0, e1, e2;  // p0 and the edges to p1, p2
  bool casts = true;
};

std::vector<Triangle> triangles_of(const Scene& scene) {
  std::vector<Triangle> triangles;
  for (const Mesh& mesh : scene.meshes)
    for (const glm::uvec3& t : mesh.triangles) {
      const dvec3 p0(mesh.positions[t.x]), p1(mesh.positions[t.y]), p2(mesh.positions[t.z]);
      triangles.push_back({p0, p1 - p0, p2 - p0, mesh.casts_shadows});
    }
  return triangles;
}

// Möller & Trumbore 1997, in double, both faces, edges included: the distance
// along unit `u` from `o` to the triangle's plane where the line crosses it.
std::optional<double> crossing(const Triangle& tri, const dvec3& o, const dvec3& u) {
  const dvec3 p = glm::cross(u, tri.e2);
  const double det = glm::dot(tri.e1, p);
  if (det == 0.0) return std::nullopt;  // parallel (or degenerate triangle)
  const dvec3 s = o - tri.p0;
  const double a = glm::dot(s, p) / det;
  if (!(a >= 0.0 && a <= 1.0)) return std::nullopt;
  const dvec3 q = glm::cross(s, tri.e1);
  const double b = glm::dot(u, q) / det;
  if (!(b >= 0.0 && a + b <= 1.0)) return std::nullopt;
  return glm::dot(tri.e2, q) / det;
}

// Length of o + t·u, t in [t0, t1], inside the volume.
double chord(const Volume& v, const dvec3& o, const dvec3& u, double t0, double t1) {
  const optics::Interval in = optics::slab_overlap(o, u, dvec3(v.min), dvec3(v.max), t0, t1);
  return in.empty() ? 0.0 : in.hi - in.lo;
}

bool inside(const Volume& v, const dvec3& x) {
  return glm::all(glm::greaterThanEqual(x, dvec3(v.min))) && glm::all(glm::lessThanEqual(x, dvec3(v.max)));
}

// One light along one view ray: visibility by its own triangle tests, the
// integrand of docs/design.md §1, and the label of the smooth piece a point is in.
class LightAlongRay {
public:
  // The view ray runs to d; `reach` bounds how far any caster lies from its points.
  LightAlongRay(const Scene& scene, const std::vector<Triangle>& triangles, const Light& light,
                const optics::Ray& ray, double d, double reach)
      : scene_(scene), light_(light), ray_(ray) {
    if (light.type == LightType::directional) travel_ = glm::normalize(dvec3(light.direction));
    // Every shadow ray from the view ray toward the light lies in the plane of the
    // view ray and the light (for a directional light: and its direction), so only
    // triangles reaching that plane can shadow it, and only inside the box around
    // the triangle eye, ray end, light (a directional light: the strip toward it,
    // cut at `reach`).
    const dvec3 end = at(d);
    dvec3 lo = glm::min(ray.origin, end), hi = glm::max(ray.origin, end);
    for (const dvec3& p : light.type == LightType::directional
                              ? std::vector{ray.origin - reach * travel_, end - reach * travel_}
                              : std::vector{dvec3(light.position)})
      lo = glm::min(lo, p), hi = glm::max(hi, p);
    const dvec3 toward = light.type == LightType::directional ? -travel_ : dvec3(light.position) - ray.origin;
    dvec3 normal = glm::cross(ray.dir, toward);
    if (!(glm::length(normal) > 1e-12 * glm::length(toward)))  // the light on the view ray's line
      normal = glm::cross(ray.dir, std::abs(ray.dir.x) < 0.9 ? dvec3(1, 0, 0) : dvec3(0, 1, 0));
    normal = glm::normalize(normal);
    for (const Triangle& t : triangles) {
      if (!t.casts) continue;
      const std::array<dvec3, 3> v{t.p0, t.p0 + t.e1, t.p0 + t.e2};
      std::array<double, 3> side;
      for (int k = 0; k < 3; ++k) side[k] = glm::dot(normal, v[k] - ray.origin);
      const double slack = 1e-12 * (1.0 + std::abs(side[0]));  // rounding of the shadow rays' directions
      if (std::min({side[0], side[1], side[2]}) > slack || std::max({side[0], side[1], side[2]}) < -slack) continue;
      const dvec3 t_lo = glm::min(v[0], glm::min(v[1], v[2])), t_hi = glm::max(v[0], glm::max(v[1], v[2]));
      const double box_slack = 1e-9 * reach;  // the box is exact: this only absorbs rounding
      if (glm::any(glm::greaterThan(t_lo, hi + box_slack)) || glm::any(glm::lessThan(t_hi, lo - box_slack))) continue;
      // Where the triangle's edges cross the plane, seen from the light on the
      // view ray: its shadow there lies between these seeds, unless the
      // crossing straddles the line through a point light parallel to the view
      // ray, where the projection passes through infinity.
      Caster caster{t};
      double lo_t = infinity, hi_t = -infinity;
      int above = 0, below = 0, crossings = 0;
      for (int k = 0; k < 3; ++k) {
        const int m = (k + 1) % 3;
        if ((side[k] > 0.0) == (side[m] > 0.0) && side[k] != 0.0) continue;
        const double f = side[k] == side[m] ? 0.0 : side[k] / (side[k] - side[m]);
        const dvec3 p = v[k] + f * (v[m] - v[k]);
        const double t_p = shadow_at(p);
        shadow_seeds_.push_back(t_p);
        lo_t = std::min(lo_t, t_p), hi_t = std::max(hi_t, t_p);
        const double w = light.type == LightType::directional
                             ? 1.0
                             : glm::dot(glm::cross(ray.dir, p - dvec3(light.position)), normal);
        above += w > 0.0, below += w < 0.0, ++crossings;
      }
      if (lo_t <= hi_t && crossings > 0 && (above == crossings || below == crossings)) {
        const double margin = 1e-6 * d;  // the seeds' rounding, far above it
        caster.lo = lo_t - margin, caster.hi = hi_t + margin;
      }
      casters_.push_back(caster);
    }
  }

  // Parameters along the view ray between which visibility is constant (every
  // change is where a shadow ray grazes a caster's edge, which is a seed), and
  // the optics' own crossings of the spot's cones, the beam's box and the volumes
  // (where piece() decides: a wrong seed costs a probe, not a wrong answer).
  std::vector<double> seeds(double d) const {
    std::vector<double> seeds = optics::volume_crossings(scene_, ray_.origin, ray_.dir, 0.0, d);
    if (light_.type == LightType::spot)
      for (double angle : {light_.cone_deg, light_.cone_deg - light_.edge_deg}) {
        const optics::ConeIntervals in = optics::cone_intervals(
            dvec3(light_.position), glm::normalize(dvec3(light_.direction)), optics::radians(angle), ray_.origin, ray_.dir, 0.0, d);
        for (int i = 0; i < in.count; ++i) seeds.insert(seeds.end(), {in.piece[i].x, in.piece[i].y});
      }
    if (optics::has_beam(light_)) {
      const optics::Interval in = optics::beam_interval(light_, ray_.origin, ray_.dir, 0.0, d);
      if (!in.empty()) seeds.insert(seeds.end(), {in.lo, in.hi});
    }
    seeds.insert(seeds.end(), shadow_seeds_.begin(), shadow_seeds_.end());
    return seeds;
  }

  // Which smooth piece of the integrand x is in: 0 where nothing arrives (dark,
  // outside the cone or the beam); else bit 0 set, bit 1 inside the smooth edge
  // of a spot, and one bit per bounded volume containing x from bit 2 on.
  std::uint64_t piece(double x) const {
    const dvec3 p = at(x);
    std::uint64_t label = 1;
    if (light_.type == LightType::spot) {
      const dvec3 v = p - dvec3(light_.position), axis = glm::normalize(dvec3(light_.direction));
      const double angle = std::atan2(glm::length(glm::cross(axis, v)), glm::dot(axis, v));
      const double cone = optics::radians(light_.cone_deg);
      if (angle > cone) return 0;
      if (angle > cone - optics::radians(light_.edge_deg)) label |= 2;
    }
    if (optics::has_beam(light_) && !optics::inside_beam(light_, p)) return 0;
    if (!visible(x)) return 0;
    for (std::size_t k = 0; k < scene_.volumes.size(); ++k)
      if (inside(scene_.volumes[k], p)) label |= std::uint64_t{4} << k;
    return label;
  }

  // σs·p(cos θ)·I(ω)·exp(−τ_light)/r²·exp(−τ_eye) at distance x (docs/design.md §1),
  // without visibility.
  dvec3 integrand(double x) const {
    const dvec3 p = at(x);
    const bool simplified = scene_.light_model.type == LightModelType::simplified;
    dvec3 to_light, arriving;
    double leg = 0.0;  // the light's leg in the filling medium, back to where light is emitted
    if (light_.type == LightType::directional) {
      to_light = -travel_;
      arriving = dvec3(light_.irradiance) * optics::light_map(light_, p);
      if (optics::has_beam(light_))  // emitted at the aperture: the leg back to its plane
        leg = std::max(glm::dot(p - dvec3(light_.beam->origin), travel_), 0.0);
    } else {
      const dvec3 delta = dvec3(light_.position) - p;
      leg = glm::length(delta);
      to_light = delta / leg;
      const double r = std::max(leg, optics::min_light_distance);
      const double falloff = simplified ? scene_.light_model.a1 * r * r + scene_.light_model.a0  // Nilsson eq. 2.13
                                        : r * r;
      arriving = optics::radiant_intensity(light_, -to_light) / falloff;
    }
    // θ from the light's travel (−to_light) to the way to the eye (−dir).
    const double cos_theta = glm::dot(to_light, ray_.dir);
    if (simplified)  // Nilsson eq. 2.14-2.15: isotropic, the medium only, T = 1
      return dvec3(scene_.medium.sigma_s) / (4.0 * std::numbers::pi) * arriving;
    dvec3 scattered = dvec3(scene_.medium.sigma_s) * optics::phase(scene_.medium.phase, cos_theta);
    // Optical depth: the medium on the eye's leg and on the light's leg (an
    // unbounded sun's leg has no medium: leg = 0), each volume's chords on both.
    dvec3 depth = dvec3(scene_.medium.sigma_t()) * (x + leg);
    const double light_end = light_.type == LightType::directional && !optics::has_beam(light_) ? infinity : leg;
    for (const Volume& v : scene_.volumes) {
      if (inside(v, p)) scattered += dvec3(v.sigma_s) * optics::phase(v.phase, cos_theta);
      depth += dvec3(v.sigma_t()) * (chord(v, ray_.origin, ray_.dir, 0.0, x) + chord(v, p, to_light, 0.0, light_end));
    }
    return scattered * arriving * glm::exp(-depth);
  }

  // ∫ integrand over [a, b]; for point and spot lights whose falloff is 1/r²
  // or Nilsson's 1/(a1 r² + a0) with a1 > 0 the variable is the angle φ seen
  // from the light, x = tc + r0·tan φ (Sun et al. 2005), so that dx/r² = dφ/r0
  // takes out the peak at the closest approach.
  dvec3 integral(double a, double b, double rel_tol) const {
    optics::gk::Settings settings;
    settings.rel_tol = rel_tol;
    const auto f = [&](double x) { return integrand(x); };
    if (light_.type == LightType::directional) return optics::gk::integrate<dvec3>(f, {a, b}, settings);
    const dvec3 delta = dvec3(light_.position) - ray_.origin;
    const double tc = glm::dot(delta, ray_.dir), r0 = glm::length(delta - tc * ray_.dir);
    const bool peaked = scene_.light_model.type == LightModelType::physical || scene_.light_model.a1 > 0.0f;
    if (peaked && r0 > optics::min_light_distance) {
      const auto g = [&](double phi) {
        const double c = std::cos(phi);
        return integrand(tc + r0 * std::tan(phi)) * (r0 / (c * c));
      };
      return optics::gk::integrate<dvec3>(g, {std::atan((a - tc) / r0), std::atan((b - tc) / r0)}, settings);
    }
    // Through the light (r clamped at min_light_distance) or no falloff: in x,
    // broken at the clamp's kinks and the light.
    std::vector<double> breaks{a};
    for (double t : {tc - optics::min_light_distance, tc, tc + optics::min_light_distance})
      if (t > a && t < b) breaks.push_back(t);
    breaks.push_back(b);
    return optics::gk::integrate<dvec3>(f, breaks, settings);
  }

private:
  dvec3 at(double x) const { return ray_.origin + x * ray_.dir; }

  // t where the view ray meets the line from the light through p (a
  // directional light: the line through p along its travel): o + t·d = b + s·e
  // crossed with e gives t = −((o − b) × e)·(d × e) / |d × e|²; NaN when parallel.
  double shadow_at(const dvec3& p) const {
    const bool sun = light_.type == LightType::directional;
    const dvec3 base = sun ? p : dvec3(light_.position), e = sun ? travel_ : p - base;
    const dvec3 de = glm::cross(ray_.dir, e);
    const double den = glm::dot(de, de);
    return den > 0.0 ? -glm::dot(glm::cross(ray_.origin - base, e), de) / den : std::nan("");
  }

  // V at distance x along the view ray.
  bool visible(double x) const {
    const dvec3 p = at(x);
    dvec3 u;
    double reach;
    if (light_.type == LightType::directional) {
      u = -travel_;
      reach = infinity;  // docs/decisions.md, Beams: as for any directional light
    } else {
      const dvec3 delta = dvec3(light_.position) - p;
      const double distance = glm::length(delta);
      if (distance == 0.0) return true;
      u = delta / distance;
      reach = distance * (1.0 - light_clearance);
    }
    for (const Caster& c : casters_) {
      if (x < c.lo || x > c.hi) continue;  // cannot shadow x (the filter, not the test)
      const std::optional<double> s = crossing(c.triangle, p, u);
      if (s && *s > 0.0 && *s <= reach) return false;
    }
    return true;
  }

  const Scene& scene_;
  const Light& light_;
  optics::Ray ray_;
  dvec3 travel_{0.0};  // a directional light's unit direction of travel
  struct Caster {
    Triangle triangle;
    double lo = -infinity, hi = infinity;  // the only stretch of the view ray it may shadow
  };
  std::vector<Caster> casters_;
  std::vector<double> shadow_seeds_;
};

// The pieces of [0, d] between changes of light.piece: the changes seen between
// probes — dense even ones (for the cone, the beam, the volumes), the light's
// seeds and the midpoints between consecutive seeds (so each stretch of
// constant visibility is probed however narrow) — each narrowed by bisection
// (any further change found on the way is narrowed too).
struct Piece {
  double lo, hi;
  std::uint64_t label;
};

std::vector<double> probes(const LightAlongRay& light, double d, int even) {
  std::vector<double> seeds;
  for (double t : light.seeds(d))
    if (t > 0.0 && t < d) seeds.push_back(t);
  std::sort(seeds.begin(), seeds.end());
  std::vector<double> x;
  for (int k = 1; k <= even; ++k) x.push_back(d * k / even);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    x.push_back(seeds[k]);
    x.push_back(0.5 * ((k == 0 ? 0.0 : seeds[k - 1]) + seeds[k]));
  }
  if (!seeds.empty()) x.push_back(0.5 * (seeds.back() + d));
  std::sort(x.begin(), x.end());
  return x;
}

std::vector<Piece> pieces(const LightAlongRay& light, double d, int even) {
  const double resolution = boundary_resolution * d;
  std::vector<Piece> out;
  double start = 0.0;
  std::uint64_t current = light.piece(0.0);
  // Records the changes inside (a, b), whose labels differ.
  auto narrow = [&](auto&& self, double a, std::uint64_t la, double b, std::uint64_t lb) -> void {
    if (b - a <= resolution) {
      const double edge = 0.5 * (a + b);
      out.push_back({start, edge, current});
      start = edge;
      current = lb;
      return;
    }
    const double m = 0.5 * (a + b);
    const std::uint64_t lm = light.piece(m);
    if (lm != la) self(self, a, la, m, lm);
    if (lm != lb) self(self, m, lm, b, lb);
  };
  double previous = 0.0;
  for (const double x : probes(light, d, even)) {
    const std::uint64_t label = light.piece(x);
    if (label != current) narrow(narrow, previous, current, x, label);
    previous = x;
  }
  out.push_back({start, d, current});
  return out;
}

glm::dvec3 airlight(const Scene& scene, const std::vector<Triangle>& triangles, const optics::Ray& ray,
                    const BruteForceSettings& settings) {
  if (scene.volumes.size() > 62) throw Failure("brute_force_airlight: more than 62 bounded volumes");
  const Camera& camera = scene.camera;
  double d = geometry::far_distance(camera, ray.dir);
  const double near = geometry::near_distance(camera, ray.dir);
  double farthest = 0.0;  // of a vertex from the eye
  for (const Triangle& t : triangles) {
    if (const std::optional<double> s = crossing(t, ray.origin, ray.dir); s && *s >= near && *s < d) d = *s;
    for (const dvec3& p : {t.p0, t.p0 + t.e1, t.p0 + t.e2}) farthest = std::max(farthest, glm::length(p - ray.origin));
  }
  if (!std::isfinite(d)) throw Failure("brute_force_airlight: the ray meets neither a surface nor the far plane");
  const double reach = farthest + d;  // no caster is farther from a point of the view ray
  dvec3 sum(0.0);
  for (const Light& light : scene.lights) {
    const LightAlongRay along(scene, triangles, light, ray, d, reach);
    for (const Piece& p : pieces(along, d, settings.probes))
      if (p.label != 0 && p.hi > p.lo) sum += along.integral(p.lo, p.hi, settings.rel_tol);
  }
  return sum;
}

}  // namespace

glm::dvec3 brute_force_airlight(const Scene& scene, const optics::Ray& ray, const BruteForceSettings& settings) {
  return airlight(scene, triangles_of(scene), ray, settings);
}

glm::dvec3 brute_force_airlight(const Scene& scene, int width, int height, glm::ivec2 pixel,
                                const BruteForceSettings& settings) {
  return brute_force_airlight(scene, width, height, std::vector{pixel}, settings).front();
}

std::vector<glm::dvec3> brute_force_airlight(const Scene& scene, int width, int height,
                                             const std::vector<glm::ivec2>& pixels,
                                             const BruteForceSettings& settings) {
  const std::vector<Triangle> triangles = triangles_of(scene);
  std::vector<glm::dvec3> values(pixels.size());
  tbb::parallel_for(std::size_t{0}, pixels.size(), [&](std::size_t k) {
    const optics::Ray ray =
        geometry::primary_ray(scene.camera, width, height, pixels[k].x + 0.5, pixels[k].y + 0.5);
    values[k] = airlight(scene, triangles, ray, settings);
  });
  return values;
}

}  // namespace airlight::reference
