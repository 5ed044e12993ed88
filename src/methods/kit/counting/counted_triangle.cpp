#include "methods/kit/counting/counted_triangle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/geometric.hpp>

namespace airlight::kit {
namespace {

// A homogeneous point as a finite one and a direction: (p, 1) → p; (d, 0) → d.
glm::dvec3 finite(const glm::dvec4& p) { return glm::dvec3(p); }

// counted_plane's unit normal in double (0 for a degenerate triangle).
glm::dvec3 counted_normal(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c) {
  // With one corner at infinity its direction spans the plane with the finite edge.
  glm::dvec3 n;
  if (c.w == 0.0) n = glm::cross(finite(b) - finite(a), finite(c));
  else if (b.w == 0.0) n = glm::cross(finite(b), finite(c) - finite(a));
  else if (a.w == 0.0) n = glm::cross(finite(c) - finite(b), finite(a));
  else n = glm::cross(finite(b) - finite(a), finite(c) - finite(a));
  const double length = glm::length(n);
  return length > 0.0 ? n / length : n;
}

// Where p, on the plane of triangle c, lies: its least distance inside the
// triangle's edges (negative outside), a corner at infinity standing as a
// point `far` along its direction from a finite corner.
double inside_by(const CountedTriangle& c, const glm::dvec3& p, double far) {
  const glm::dvec4 first(c.corners[c.corners[0].w != 0.0f ? 0 : 1]);
  glm::dvec3 q[3];
  for (int k = 0; k < 3; ++k) {
    const glm::dvec4 corner(c.corners[k]);
    q[k] = corner.w != 0.0 ? finite(corner) : finite(first) + far * glm::normalize(finite(corner));
  }
  const glm::dvec3 m = glm::cross(q[1] - q[0], q[2] - q[0]);
  double least = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 inward = glm::cross(m, q[(k + 1) % 3] - q[k]);
    const double length = glm::length(inward);
    if (!(length > 0.0)) return -std::numeric_limits<double>::infinity();
    least = std::min(least, glm::dot(p - q[k], inward) / length);
  }
  return least;
}

}  // namespace

glm::vec4 counted_plane(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c) {
  const glm::dvec3 unit = counted_normal(a, b, c);
  const glm::dvec3 point = finite(a.w != 0.0 ? a : b);
  return glm::vec4(glm::vec3(unit), static_cast<float>(glm::dot(unit, point)));
}

std::vector<EyePlane> take_planes_at_eye(std::vector<CountedTriangle>& triangles, size_t first, int light,
                                         const Light& source, const glm::dvec3& eye, size_t room, glm::dvec3& beside) {
  const bool directional = source.type == LightType::directional;
  struct AtEye {
    size_t index;
    glm::dvec3 normal;
  };
  std::vector<AtEye> found;
  std::vector<size_t> edge_on;  // through the eye, the eye outside them: a ray from it never crosses them
  double scale = 0.0;           // the largest magnitude among those found
  for (size_t i = first; i < triangles.size(); ++i) {
    const CountedTriangle& c = triangles[i];
    if (c.light_weight.x != light || c.light_weight.y == 0) continue;
    // In double, oriented as the plane the GPU counts by (its method may have built it otherwise).
    glm::dvec3 n = counted_normal(glm::dvec4(c.corners[0]), glm::dvec4(c.corners[1]), glm::dvec4(c.corners[2]));
    if (glm::dot(n, glm::dvec3(c.plane)) < 0.0) n = -n;
    double magnitude = std::max(glm::length(eye), directional ? 0.0 : glm::length(glm::dvec3(source.position)));
    for (const glm::vec4& corner : c.corners)
      if (corner.w != 0.0f) magnitude = std::max(magnitude, glm::length(glm::dvec3(corner)));
    const glm::dvec3 on_plane(c.corners[c.corners[0].w != 0.0f ? 0 : 1]);
    const double distance = glm::dot(n, eye - on_plane), tolerance = 1e-5 * magnitude;
    // Shadow boundaries only, planes along the light's rays: a plane through the
    // eye that is not (a caster's own face) is the eye on a surface, which the
    // crossing test decides exactly (crossings.vert.glsl); on a box's edge the eye
    // lies on two such planes at once (random scene 24).
    const double off_light = directional ? std::abs(glm::dot(n, glm::dvec3(source.direction)))
                                         : std::abs(glm::dot(n, glm::dvec3(source.position) - on_plane)) / magnitude;
    if (!(glm::length(n) > 0.0 && std::abs(distance) <= tolerance && off_light <= 1e-5)) continue;
    // On an edge (random scene 24: the eye on a box's edge, on two faces' planes
    // at once), which side a ray takes depends on more than this plane: drawn.
    const double inside = inside_by(c, eye - distance * n, 1e6 * magnitude);
    if (inside < -tolerance) edge_on.push_back(i);
    if (inside > tolerance) found.push_back({i, n});
    if (std::abs(inside) > tolerance) scale = std::max(scale, magnitude);
  }
  if (found.size() > room) return {};
  const auto take_out = [&] {
    for (const AtEye& f : found) triangles[f.index].light_weight.y = 0;
    for (const size_t i : edge_on) triangles[i].light_weight.y = 0;
  };
  if (found.empty()) {
    take_out();
    return {};
  }
  // Off the eye against the normals' sum, twice the planes' tolerance: on the
  // negative side of each (checked), and inside them still.
  glm::dvec3 away(0.0);
  for (const AtEye& f : found) away -= f.normal;
  if (!(glm::length(away) > 0.5)) return {};
  beside = eye + 2e-5 * scale * glm::normalize(away);
  std::vector<EyePlane> planes;
  for (const AtEye& f : found) {
    CountedTriangle& c = triangles[f.index];
    const glm::dvec3 on_plane(c.corners[c.corners[0].w != 0.0f ? 0 : 1]);
    if (!(glm::dot(f.normal, beside - on_plane) < 0.0)) return {};
    planes.push_back({glm::vec3(f.normal), light, c.light_weight.y});
  }
  take_out();
  return planes;
}

}  // namespace airlight::kit
