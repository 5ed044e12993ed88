#include "methods/kit/planes/light_bounds.hpp"

#include "optics/light.hpp"

#include <algorithm>
#include <chrono>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

namespace airlight::kit {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();


// Half-space through `point` keeping the side `inward` points to.
glm::vec4 half_space(const glm::dvec3& inward, const glm::dvec3& point) {
  return glm::vec4(glm::vec3(inward), static_cast<float>(-glm::dot(inward, point)));
}

// The 8 tangent planes of a right octagonal pyramid circumscribing the cone
// (apex, axis, half-angle α < 90°): the plane touching the cone along the
// generator at azimuth φ has outward normal cos α·radial(φ) − sin α·axis. The
// pyramid exceeds the cone by 5% in cross-section (8 tan(π/8)/π).
std::vector<glm::vec4> cone_pyramid(const Light& light) {
  const glm::dvec3 apex(light.position), axis = glm::normalize(glm::dvec3(light.direction));
  glm::dvec3 right, up;
  optics::gobo_frame(light, right, up);
  const double a = optics::radians(light.cone_deg);
  std::vector<glm::vec4> planes;
  for (int k = 0; k < 8; ++k) {
    const double phi = k * std::numbers::pi / 4.0;
    const glm::dvec3 radial = std::cos(phi) * right + std::sin(phi) * up;
    planes.push_back(half_space(std::sin(a) * axis - std::cos(a) * radial, apex));
  }
  return planes;
}

// The beam's oriented box: its aperture's four edges and its two ends.
std::vector<glm::vec4> beam_box(const Light& light) {
  const Beam& beam = *light.beam;
  const glm::dvec3 o(beam.origin), dir = glm::normalize(glm::dvec3(light.direction));
  glm::dvec3 right, up;
  optics::gobo_frame(light, right, up);
  const double hw = 0.5 * beam.size.x, hh = 0.5 * beam.size.y;
  return {half_space(right, o - hw * right), half_space(-right, o + hw * right),
          half_space(up, o - hh * up),       half_space(-up, o + hh * up),
          half_space(dir, o),                half_space(-dir, o + double(beam.length) * dir)};
}

// (s, t) in (-1, 1)² over a grid of n × n cell centres.
template <typename F>
void for_grid(int n, F&& f) {
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) f(2.0 * (i + 0.5) / n - 1.0, 2.0 * (j + 0.5) / n - 1.0);
}

// Casts rays from a point light or spot over the directions it lights; false
// when one escapes.
bool trace_from_apex(const Light& light, const reference::RayCaster& rays, std::vector<glm::dvec3>& hull) {
  const glm::dvec3 apex(light.position);
  hull.push_back(apex);
  bool bounded = true;
  auto cast = [&](const glm::dvec3& d) {
    const glm::dvec3 dir = glm::normalize(d);
    if (light.type == LightType::spot && optics::spot_cone(light, dir) <= 0.0) return;
    const auto hit = rays.intersect({apex, dir}, 0.0, infinity);
    if (hit) hull.push_back(apex + hit->t * dir);
    bounded = bounded && hit.has_value();
  };
  if (light.type == LightType::spot && light.cone_deg < 90.0f) {
    // The square circumscribing the cone, as the gobo's (optics::gobo_uv).
    glm::dvec3 right, up;
    optics::gobo_frame(light, right, up);
    const glm::dvec3 axis = glm::normalize(glm::dvec3(light.direction));
    const double tan_cone = std::tan(optics::radians(light.cone_deg));
    for_grid(lit_region_rays, [&](double s, double t) { cast(axis + tan_cone * (s * right + t * up)); });
  } else {
    for (int axis = 0; axis < 3; ++axis)
      for (double sign : {-1.0, 1.0})
        for_grid(lit_region_rays, [&](double s, double t) {
          glm::dvec3 d(0.0);
          d[axis] = sign;
          d[(axis + 1) % 3] = s;
          d[(axis + 2) % 3] = t;
          cast(d);
        });
  }
  return bounded;
}

// Casts the beam's parallel rays from its aperture to the first surface or the
// beam's end: a beam is always bounded.
void trace_beam(const Light& light, const reference::RayCaster& rays, std::vector<glm::dvec3>& hull) {
  const Beam& beam = *light.beam;
  const glm::dvec3 dir = glm::normalize(glm::dvec3(light.direction));
  glm::dvec3 right, up;
  optics::gobo_frame(light, right, up);
  for_grid(lit_region_rays, [&](double s, double t) {
    const glm::dvec3 start = glm::dvec3(beam.origin) + 0.5 * (s * beam.size.x * right + t * beam.size.y * up);
    const auto hit = rays.intersect({start, dir}, 0.0, beam.length);
    hull.push_back(start);
    hull.push_back(start + (hit ? hit->t : double(beam.length)) * dir);
  });
}

// Whether a light's bounds can differ between a and b (colours cannot change them).
bool same_reach(const Light& a, const Light& b) {
  const bool beams = a.beam.has_value() == b.beam.has_value() &&
                     (!a.beam || (a.beam->origin == b.beam->origin && a.beam->size == b.beam->size &&
                                  a.beam->length == b.beam->length));
  return a.type == b.type && a.position == b.position && a.direction == b.direction && a.cone_deg == b.cone_deg &&
         a.gobo_up == b.gobo_up && beams;
}

}  // namespace

LightBounds light_bounds(const Light& light, const reference::RayCaster& rays) {
  LightBounds v;
  switch (light.type) {
    case LightType::point: v.bounded = trace_from_apex(light, rays, v.hull); break;
    case LightType::spot:
      if (light.cone_deg < 90.0f) v.clip = cone_pyramid(light);
      v.bounded = trace_from_apex(light, rays, v.hull);
      break;
    case LightType::directional:
      if (!light.beam) break;  // lit everywhere
      v.clip = beam_box(light);
      trace_beam(light, rays, v.hull);
      v.bounded = true;
      break;
  }
  if (!v.bounded) v.hull.clear();
  return v;
}

double lit_far_depth(const LightBounds& volume, const geometry::CameraBasis& camera, double far) {
  if (!volume.bounded) return far;
  double deepest = 0.0;
  for (const glm::dvec3& p : volume.hull) deepest = std::max(deepest, glm::dot(p - camera.position, camera.forward));
  return std::min(far, 1.01 * deepest);
}

}  // namespace airlight::kit

namespace airlight::kit {

void FrameLightBounds::prepare(const Scene& scene) {
  scene_ = scene;
  rays_.reset();
  transforms_.clear();
  lights_.clear();
  bounds_.clear();
}

void FrameLightBounds::update(const FrameInputs& inputs) {
  const auto start = std::chrono::steady_clock::now();
  const bool moved = !rays_ || inputs.transforms != transforms_;
  if (moved) {
    // Light passes through meshes that cast no shadows: only casters bound
    // what it reaches (random scene 98: a beam's rays stopped at an open mesh
    // in front of its aperture, and planes drew none of its shaft).
    Scene casters = posed_scene(scene_, inputs);
    std::erase_if(casters.meshes, [](const Mesh& m) { return !m.casts_shadows; });
    rays_ = std::make_unique<reference::RayCaster>(casters);
    transforms_ = inputs.transforms;
  }
  const size_t known = moved ? 0 : std::min(lights_.size(), inputs.lights.size());
  rebuilt_ = 0;
  bounds_.resize(inputs.lights.size());
  lights_.resize(inputs.lights.size());
  for (size_t i = 0; i < inputs.lights.size(); ++i) {
    if (i < known && same_reach(lights_[i], inputs.lights[i])) continue;
    bounds_[i] = light_bounds(inputs.lights[i], *rays_);
    lights_[i] = inputs.lights[i];
    ++rebuilt_;
  }
  seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace airlight::kit
