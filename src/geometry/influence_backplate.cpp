#include "geometry/influence_backplate.hpp"

#include "optics/light.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>

namespace airlight::geometry {

namespace {

BeamPolygon square(const glm::dvec3& centre, const glm::dvec3& half_u, const glm::dvec3& half_v) {
  return {{centre - half_u - half_v, centre + half_u - half_v, centre + half_u + half_v, centre - half_u + half_v}, -1};
}

// Faces of the cube of half-size `half` about `centre` in the frame (axis, right, up): the
// face ahead always, the four beside the axis if `sides`, the one behind if `behind`.
std::vector<BeamPolygon> cube_faces(const glm::dvec3& centre, const glm::dvec3& axis, const glm::dvec3& right,
                                    const glm::dvec3& up, double half, bool sides, bool behind) {
  std::vector<BeamPolygon> faces{square(centre + half * axis, half * right, half * up)};
  if (sides)
    for (const glm::dvec3& e : {right, -right, up, -up})
      faces.push_back(square(centre + half * e, half * axis, half * glm::cross(axis, e)));
  if (behind) faces.push_back(square(centre - half * axis, half * right, half * up));
  return faces;
}

}  // namespace

std::vector<BeamPolygon> influence_backplate(const Light& light, double far_distance) {
  glm::dvec3 right, up;
  optics::gobo_frame(light, right, up);
  const glm::dvec3 axis = glm::normalize(glm::dvec3(light.direction));
  const glm::dvec3 position(light.position);
  if (light.type == LightType::directional) {
    if (!light.beam) return {square(far_distance * axis, far_distance * right, far_distance * up)};
    const Beam& beam = *light.beam;
    const glm::dvec3 far_face = glm::dvec3(beam.origin) + static_cast<double>(beam.length) * axis;
    return {square(far_face, 0.5 * beam.size.x * right, 0.5 * beam.size.y * up)};
  }
  if (light.type == LightType::point) return cube_faces(position, axis, right, up, far_distance, true, true);
  const double cone = optics::radians(light.cone_deg);
  if (cone <= std::numbers::pi / 4.0) {
    const double half = far_distance * std::tan(cone);
    return {square(position + far_distance * axis, half * right, half * up)};
  }
  // Seen from the centre, the cone (half-angle about the axis) reaches the faces beside the
  // axis beyond 45° and the face behind beyond the angle to its nearest corner, acos(−1/√3).
  return cube_faces(position, axis, right, up, far_distance, true, cone > std::acos(-1.0 / std::sqrt(3.0)));
}

}  // namespace airlight::geometry
