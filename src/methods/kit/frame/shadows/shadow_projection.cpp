#include "methods/kit/frame/shadows/shadow_projection.hpp"

#include "methods/kit/frame/model_of.hpp"
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

Bounds caster_bounds(const Mesh& mesh) {
  Bounds b;
  if (!mesh.casts_shadows) return b;
  for (const glm::vec3& p : mesh.positions) b.add(glm::dvec3(p));
  return b;
}

Bounds world_bounds(const std::vector<Bounds>& meshes, const std::vector<glm::mat4>& transforms) {
  Bounds b;
  for (size_t m = 0; m < meshes.size(); ++m) {
    const Bounds& local = meshes[m];
    if (local.empty()) continue;
    const glm::dmat4 model = glm::dmat4(model_of(transforms, m));
    for (int k = 0; k < 8; ++k) b.add(glm::dvec3(model * glm::dvec4(local.corner(k), 1.0)));
  }
  return b;
}

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

// A shadow texel's world size at distance r is (per_distance·r + constant) /
// resolution: read off an engine's projection (perspective: 2/P₁₁ at unit
// distance; orthographic: 2/P₁₁ everywhere), the larger of the two axes.
Projection engine_projection(const EngineShadow& e) {
  const glm::mat4& p = e.projection;
  const float across = 2.0f / std::max(std::min(std::abs(p[0][0]), std::abs(p[1][1])), 1e-30f);
  const bool perspective = p[3][3] == 0.0f;
  return {p * e.view, perspective ? across : 0.0f, perspective ? 0.0f : across};
}

// The window depth a projection gives its far plane (1, or 0 under reversed-Z):
// where an engine cleared its depth buffer, no surface or occluder was drawn.
float far_window_depth(const glm::mat4& projection) {
  const glm::vec4 near = projection * glm::vec4(0, 0, -1, 1), further = projection * glm::vec4(0, 0, -2, 1);
  return further.z / further.w < near.z / near.w ? 0.0f : 1.0f;
}

}  // namespace airlight::kit
