#include "methods/kit/frame/shadows/shadow_projection.hpp"

#include "optics/light.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

namespace airlight::kit {
namespace {

// Far plane of a light's perspective maps: beyond every occluder. The near plane
// at 1e-4 of it loses only occluders within millimetres of the light.
struct NearFar {
  double near, far;
};
NearFar perspective_range(const glm::dvec3& apex, const Bounds& b) {
  double far = 0.0;
  for (int k = 0; k < 8; ++k) far = std::max(far, glm::length(b.corner(k) - apex));
  far = far * 1.01 + 1e-3;
  return {far * 1e-4, far};
}

glm::dvec3 up_hint(const glm::dvec3& dir) {
  return std::abs(dir.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
}

}  // namespace

// A spot's cone in a square perspective map of field 2·cone.
Projection spot_projection(const Light& light, const Bounds& b) {
  const glm::dvec3 apex(light.position), axis = glm::normalize(glm::dvec3(light.direction));
  const NearFar range = perspective_range(apex, b);
  const double cone = optics::radians(light.cone_deg);
  const glm::dmat4 view = glm::lookAt(apex, apex + axis, up_hint(axis));
  const glm::dmat4 proj = glm::perspective(2.0 * cone, 1.0, range.near, range.far);
  return {glm::mat4(proj * view), static_cast<float>(2.0 * std::tan(cone)), 0.0f};
}

// A directional light: orthographic along the light, its depth range over the
// scene's bounds (every occluder), its x/y extent over the bounds too (every
// ray through them lands inside; points outside are lit) — or, for a beam,
// over the beam's aperture: only points inside the beam are lit, so the
// texels are spent there.
Projection directional_projection(const Light& light, const Bounds& b) {
  const glm::dvec3 dir = glm::normalize(glm::dvec3(light.direction));
  glm::dvec3 eye = 0.5 * (b.lo + b.hi), up = up_hint(dir);
  if (optics::has_beam(light)) {
    glm::dvec3 right;
    optics::gobo_frame(light, right, up);  // lookAt's x is then dir × up = right: the beam's frame
    eye = glm::dvec3(light.beam->origin);
  }
  const glm::dmat4 view = glm::lookAt(eye, eye + dir, up);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 p(view * glm::dvec4(b.corner(k), 1.0));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (optics::has_beam(light)) {
    const glm::dvec2 half = 0.5 * glm::dvec2(light.beam->size);
    lo = glm::dvec3(-half, lo.z);
    hi = glm::dvec3(half, hi.z);
  }
  const double margin = 1e-3 * glm::length(hi - lo) + 1e-6;
  lo -= margin;
  hi += margin;
  const glm::dmat4 proj = glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z, -lo.z);  // view looks along -z
  return {glm::mat4(proj * view), 0.0f, static_cast<float>(std::max(hi.x - lo.x, hi.y - lo.y))};
}

// Cube faces in GL's order +x −x +y −y +z −z, with the up vectors that make a
// face rendered into a bottom-left-origin framebuffer agree with cube sampling.
std::array<glm::mat4, 6> cube_face_matrices(const glm::dvec3& apex, const Bounds& b) {
  static const std::array<std::pair<glm::dvec3, glm::dvec3>, 6> faces{{{{1, 0, 0}, {0, -1, 0}},
                                                                        {{-1, 0, 0}, {0, -1, 0}},
                                                                        {{0, 1, 0}, {0, 0, 1}},
                                                                        {{0, -1, 0}, {0, 0, -1}},
                                                                        {{0, 0, 1}, {0, -1, 0}},
                                                                        {{0, 0, -1}, {0, -1, 0}}}};
  const NearFar range = perspective_range(apex, b);
  const glm::dmat4 proj = glm::perspective(0.5 * std::numbers::pi, 1.0, range.near, range.far);
  std::array<glm::mat4, 6> matrices;
  for (int f = 0; f < 6; ++f)
    matrices[f] = glm::mat4(proj * glm::lookAt(apex, apex + faces[f].first, faces[f].second));
  return matrices;
}

int shadow_kind(const Light& light, const Bounds& bounds, const EngineShadow* engine) {
  if (engine) return engine->kind == EngineShadow::Kind::cube ? shadow_cube : shadow_map;
  if (bounds.empty()) return shadow_none;  // nothing can occlude
  if (light.type == LightType::point) return shadow_cube;
  if (light.type == LightType::spot && light.cone_deg >= wide_spot_deg) return shadow_cube;
  return shadow_map;
}

}  // namespace airlight::kit
