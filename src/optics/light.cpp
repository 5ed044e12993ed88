#include "optics/light.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>

namespace airlight::optics {
namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

glm::dvec3 spot_axis(const Light& light) { return glm::normalize(glm::dvec3(light.direction)); }

// Hermite smoothstep of t clamped to [0, 1].
double smoothstep01(double t) {
  t = std::clamp(t, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// The gobo's right and up axes (DESIGN §1). If gobo_up is parallel to the axis
// (the loader prevents it) another world axis stands in, so the frame is never NaN.
void gobo_frame(const Light& light, glm::dvec3& right, glm::dvec3& up) {
  const glm::dvec3 axis = spot_axis(light);
  glm::dvec3 side = glm::cross(axis, glm::dvec3(light.gobo_up));
  if (glm::dot(side, side) < 1e-24) side = glm::cross(axis, glm::dvec3(0, 0, 1));
  if (glm::dot(side, side) < 1e-24) side = glm::cross(axis, glm::dvec3(1, 0, 0));
  right = glm::normalize(side);
  up = glm::cross(right, axis);
}

bool inside_unit_square(const glm::dvec2& uv) {
  return uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0;
}

glm::dvec3 gobo_colour(const Light& light, const glm::dvec3& dir) {
  if (!light.gobo || light.gobo->empty()) return glm::dvec3(1.0);
  const glm::dvec2 uv = gobo_uv(light, dir);
  return inside_unit_square(uv) ? sample_gobo(*light.gobo, uv) : glm::dvec3(0.0);
}

}  // namespace

double spot_cone(const Light& light, const glm::dvec3& dir) {
  const double cos_angle = std::clamp(glm::dot(spot_axis(light), dir), -1.0, 1.0);
  const double angle = std::acos(cos_angle);
  const double cone = radians(light.cone_deg);
  const double edge = radians(light.edge_deg);
  if (edge <= 0.0) return angle <= cone ? 1.0 : 0.0;  // Nilsson eq. 2.9: hard cut
  return smoothstep01((cone - angle) / edge);          // 1 at cone - edge, 0 at cone
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

glm::dvec3 radiant_intensity(const Light& light, const glm::dvec3& dir) {
  switch (light.type) {
    case LightType::point: return glm::dvec3(light.intensity);
    case LightType::spot:
      return glm::dvec3(light.intensity) * spot_cone(light, dir) * gobo_colour(light, dir);
    case LightType::directional: return glm::dvec3(light.irradiance);
  }
  return glm::dvec3(0.0);
}

Arrival arrival(const Light& light, const LightModel& model, const glm::dvec3& x) {
  Arrival a;
  if (light.type == LightType::directional) {
    a.irradiance = glm::dvec3(light.irradiance);
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
