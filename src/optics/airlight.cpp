#include "optics/airlight.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <vector>

#include "optics/falloff.hpp"
#include "optics/gauss_kronrod.hpp"
#include "optics/light.hpp"
#include "optics/media.hpp"

namespace airlight::optics {
namespace {

glm::dvec3 at(const Ray& ray, double x) { return ray.origin + x * ray.dir; }

// The 1/r² peak at the point of closest approach to a point or spot light.
std::vector<double> closest_approach_breaks(const Ray& ray, const glm::dvec3& light, double span) {
  const glm::dvec3 delta = light - ray.origin;
  const double tc = glm::dot(delta, ray.dir);
  return falloff_breaks(tc, glm::length(delta - tc * ray.dir), span);
}

// The ends of the parts of [t0, t1] inside the spot's inner cone (cone - edge),
// where the smooth edge starts: the cone factor has a kink there. (The outer
// cone's ends bound the integral itself.)
std::vector<double> inner_cone_breaks(const Ray& ray, const Light& light, double t0, double t1) {
  const double inner = radians(light.cone_deg - light.edge_deg);
  if (inner <= 0.0) return {};  // no inner cone: the edge reaches the axis
  const ConeIntervals lit = cone_intervals(glm::dvec3(light.position), glm::normalize(glm::dvec3(light.direction)),
                                           inner, ray.origin, ray.dir, t0, t1);
  std::vector<double> breaks;
  for (int i = 0; i < lit.count; ++i) breaks.insert(breaks.end(), {lit.piece[i].x, lit.piece[i].y});
  return breaks;
}

// Where the integrand is not smooth (or peaks), plus min_segments even panels.
std::vector<double> breakpoints(const Scene& scene, const Light& light, const Ray& ray, double t0,
                                double t1, int min_segments) {
  const double span = t1 - t0;
  std::vector<double> breaks = volume_crossings(scene, ray.origin, ray.dir, t0, t1);
  breaks.insert(breaks.end(), {t0, t1});
  const int n = std::max(1, min_segments);
  for (int i = 1; i < n; ++i) breaks.push_back(t0 + span * i / n);
  if (light.type != LightType::directional) {
    for (double t : closest_approach_breaks(ray, glm::dvec3(light.position), span)) breaks.push_back(t);
  }
  if (light.type == LightType::spot)
    for (double t : inner_cone_breaks(ray, light, t0, t1)) breaks.push_back(t);
  std::erase_if(breaks, [&](double t) { return !(t >= t0 && t <= t1); });
  std::sort(breaks.begin(), breaks.end());
  const double merge = 1e-12 * span;
  breaks.erase(std::unique(breaks.begin(), breaks.end(),
                           [&](double a, double b) { return b - a <= merge; }),
               breaks.end());
  breaks.back() = t1;  // unique() may have kept a neighbour within `merge` instead
  return breaks;
}

// Narrows [lo, hi] (visibility differs at its ends) to width <= resolution.
std::array<double, 2> locate_boundary(const Visibility& visible, const Ray& ray, double lo,
                                      double hi, double resolution) {
  const bool lit_lo = visible(at(ray, lo));
  while (hi - lo > resolution) {
    const double mid = 0.5 * (lo + hi);
    (visible(at(ray, mid)) == lit_lo ? lo : hi) = mid;
  }
  return {lo, hi};
}

}  // namespace

glm::dvec3 inscatter(const Scene& scene, const Light& light, const Ray& ray, double x) {
  const glm::dvec3 p = at(ray, x);
  const Arrival in = arrival(light, scene.light_model, p);
  if (in.irradiance == glm::dvec3(0.0)) return glm::dvec3(0.0);
  // cos θ between the light's travel (-to_light) and the way to the eye (-dir).
  const double cos_theta = glm::dot(in.to_light, ray.dir);
  const glm::dvec3 depth = light_leg_depth(scene, light, p) + eye_leg_depth(scene, ray.origin, p);
  return scattering(scene, p, cos_theta) * in.irradiance * glm::exp(-depth);
}

namespace {

// ∫_{t0}^{t1} V·e dx over a part of the ray where the light reaches (the whole
// ray, a beam's box, a piece inside a spot's cone): min_segments panels across
// that part, breaks where e is not smooth, G7K15 with shadow boundaries located.
glm::dvec3 integrate_part(const Scene& scene, const Light& light, const Ray& ray, double t0, double t1,
                          const Visibility& visible, const QuadratureSettings& settings) {
  if (!(t1 > t0)) return glm::dvec3(0.0);
  const double resolution = 1e-6 * (t1 - t0);  // of shadow boundaries
  auto evaluate = [&](double a, double b) {
    // V is probed at the nodes and at the panel's ends: a change between an end
    // and its nearest node (0.4% of the panel) is located too.
    const std::array<double, gk::node_count> nodes = gk::nodes(a, b);
    std::array<double, gk::node_count + 2> x;
    x.front() = a, x.back() = b;
    std::copy(nodes.begin(), nodes.end(), x.begin() + 1);
    std::array<bool, gk::node_count + 2> lit;
    for (std::size_t i = 0; i < x.size(); ++i) lit[i] = !visible || visible(at(ray, x[i]));
    gk::Evaluation<glm::dvec3> ev;
    if (b - a > resolution) {
      for (std::size_t i = 0; i + 1 < x.size(); ++i) {
        if (lit[i] == lit[i + 1]) continue;
        const std::array<double, 2> edge = locate_boundary(visible, ray, x[i], x[i + 1], resolution);
        // Within resolution of an end (a surface shadowing its own point at t1):
        // nothing to split off, and a refused split would leave no estimate.
        if (!(edge[0] > a && edge[1] < b)) continue;
        ev.split = edge;
        return ev;
      }
    }
    std::array<glm::dvec3, gk::node_count> fx;
    for (int i = 0; i < gk::node_count; ++i)
      fx[i] = lit[i + 1] ? inscatter(scene, light, ray, nodes[i]) : glm::dvec3(0.0);
    ev.estimate = gk::apply<glm::dvec3>(a, b, fx);
    return ev;
  };
  gk::Settings gk_settings;
  gk_settings.rel_tol = settings.rel_tol;
  gk_settings.max_depth = settings.max_depth;
  return gk::integrate_panels<glm::dvec3>(
      evaluate, breakpoints(scene, light, ray, t0, t1, settings.min_segments), gk_settings);
}

}  // namespace

glm::dvec3 airlight_quadrature(const Scene& scene, const Light& light, const Ray& ray, double t0,
                               double t1, const Visibility& visible,
                               const QuadratureSettings& settings) {
  if (has_beam(light)) {  // nothing outside the box, a jump at its faces: integrate inside only
    const Interval inside = beam_interval(light, ray.origin, ray.dir, t0, t1);
    return integrate_part(scene, light, ray, inside.lo, inside.hi, visible, settings);
  }
  if (light.type == LightType::spot) {  // likewise inside the cone, so its panels sample only lit ground
    const ConeIntervals inside = cone_intervals(glm::dvec3(light.position), glm::normalize(glm::dvec3(light.direction)),
                                                radians(light.cone_deg), ray.origin, ray.dir, t0, t1);
    glm::dvec3 sum(0.0);
    for (int i = 0; i < inside.count; ++i)
      sum += integrate_part(scene, light, ray, inside.piece[i].x, inside.piece[i].y, visible, settings);
    return sum;
  }
  return integrate_part(scene, light, ray, t0, t1, visible, settings);
}

}  // namespace airlight::optics
