#include "geometry/bounding_volumes.hpp"

#include "core/solid.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <glm/common.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

namespace airlight::geometry {
namespace {

// The world-space axis-aligned box of the vertices. Its float centre and half-size may move
// the min and max by an ulp, far below the beam trees' ε.
OrientedBox vertex_box(const Mesh& mesh) {
  if (mesh.positions.empty()) throw Failure("bounding volumes: " + mesh.name + " has no vertices");
  glm::vec3 lo = mesh.positions.front(), hi = lo;
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return {0.5f * (lo + hi), glm::mat3(1.0f), 0.5f * (hi - lo)};
}

// The header's computed inner volume. Bisection is sound because a box inside the mesh
// holds every smaller copy of it about the same centre; each candidate is tested as stored
// (float).
std::optional<OrientedBox> inner_box(const Mesh& mesh, const OrientedBox& box) {
  if (!solid::closed(mesh.positions, mesh.triangles) || !glm::all(glm::greaterThan(box.half, glm::vec3(0.0f))))
    return std::nullopt;
  glm::dvec3 sum(0.0);
  for (const glm::vec3& p : mesh.positions) sum += glm::dvec3(p);
  const glm::vec3 center(sum / double(mesh.positions.size()));
  if (!solid::inside(mesh.positions, mesh.triangles, center)) return std::nullopt;
  const glm::vec3 room = (box.half - glm::abs(center - box.center)) / box.half;  // per axis, as a scale
  const auto scaled = [&](float s) { return OrientedBox{center, glm::mat3(1.0f), s * box.half}; };
  float lo = 0.0f, hi = std::min({room.x, room.y, room.z});
  for (int i = 0; i < 20; ++i) {  // to 2⁻²⁰ of the room: a millionth of the box's size
    const float mid = 0.5f * (lo + hi);
    (solid::box_inside(mesh.positions, mesh.triangles, scaled(mid)) ? lo : hi) = mid;
  }
  if (lo == 0.0f) return std::nullopt;
  return scaled(lo);
}

bool contains(const OrientedBox& box, const glm::vec3& p) {
  const glm::vec3 local = glm::transpose(box.axes) * (p - box.center);
  return glm::all(glm::lessThanEqual(glm::abs(local), box.half));
}

std::vector<BeamPolygon> outer_faces(std::span<const BoundingVolumes> volumes) {
  std::vector<BeamPolygon> faces;
  for (size_t k = 0; k < volumes.size(); ++k)
    for (BeamPolygon& face : box_faces(volumes[k].outer, int(k))) faces.push_back(std::move(face));
  return faces;
}

std::vector<BeamPolygon> inner_faces(std::span<const BoundingVolumes> volumes,
                                     const LightOrigin& light) {
  std::vector<BeamPolygon> faces;
  for (size_t k = 0; k < volumes.size(); ++k) {
    if (!volumes[k].inner || (!light.directional && contains(volumes[k].outer, light.position)))
      continue;
    for (BeamPolygon& face : box_faces(*volumes[k].inner, int(k))) faces.push_back(std::move(face));
  }
  return faces;
}

}  // namespace

BoundingVolumes bounding_volumes(const Mesh& mesh) {
  const OrientedBox box = vertex_box(mesh);
  return {mesh.outer_box.value_or(box), mesh.inner_box ? mesh.inner_box : inner_box(mesh, box)};
}

std::vector<BeamPolygon> box_faces(const OrientedBox& box, int source) {
  // In double from the box's own numbers, so that each face is planar to double rounding.
  const glm::dvec3 c(box.center);
  glm::dvec3 e[3];
  for (int i = 0; i < 3; ++i) e[i] = double(box.half[i]) * glm::dvec3(box.axes[i]);
  std::vector<BeamPolygon> faces;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 &u = e[(i + 1) % 3], &v = e[(i + 2) % 3];
    for (const double side : {-1.0, 1.0}) {
      const glm::dvec3 m = c + side * e[i];
      faces.push_back({{m - u - v, m + u - v, m + u + v, m - u + v}, source});
    }
  }
  return faces;
}

LightRegions::LightRegions(const LightOrigin& light, std::span<const BoundingVolumes> volumes)
    : LightRegions(light, outer_faces(volumes), inner_faces(volumes, light),
                   !light.directional && std::any_of(volumes.begin(), volumes.end(), [&](const BoundingVolumes& v) {
                     return contains(v.outer, light.position);
                   })) {}

LightRegions::LightRegions(const LightOrigin& light, const std::vector<BeamPolygon>& outer_faces,
                           const std::vector<BeamPolygon>& inner_faces, bool surrounded)
    : epsilon_(beam_epsilon(light, outer_faces)),
      surrounded_(surrounded),
      outer_(light, outer_faces, epsilon_),
      inner_(light, inner_faces, epsilon_) {}

LightRegions::Region LightRegions::classify(const glm::dvec3& p) const {
  if (outer_.classify(p) == BeamTree::Side::lit) return surrounded_ ? Region::uncertain : Region::fully_lit;
  if (inner_.classify(p) == BeamTree::Side::shadowed) return Region::unlit;
  return Region::uncertain;
}

void LightRegions::partition(const BeamPolygon& polygon, std::vector<BeamPolygon>& fully_lit,
                             std::vector<BeamPolygon>& uncertain,
                             std::vector<BeamPolygon>& unlit) const {
  std::vector<BeamPolygon> shadowed;
  outer_.partition(polygon, surrounded_ ? uncertain : fully_lit, shadowed);
  for (const BeamPolygon& part : shadowed) inner_.partition(part, uncertain, unlit);
}

}  // namespace airlight::geometry
