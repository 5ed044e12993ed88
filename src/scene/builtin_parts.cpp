#include "scene/builtin_parts.hpp"
#include "scene/light_defaults.hpp"

#include <algorithm>
#include <array>
#include <glm/geometric.hpp>

namespace airlight::scene_builtin {

using namespace scene_mesh;

namespace {

std::array<glm::vec3, 8> corners(const Extent& e) {
  std::array<glm::vec3, 8> c;
  for (int k = 0; k < 8; ++k)
    c[k] = {(k & 1) ? e.max.x : e.min.x, (k & 2) ? e.max.y : e.min.y, (k & 4) ? e.max.z : e.min.z};
  return c;
}

}  // namespace

Mesh place(Mesh mesh, const Transform& transform, Color albedo, const std::string& name) {
  apply(transform, mesh);
  mesh.albedo = albedo;
  mesh.name = name;
  return mesh;
}

Mesh place(Mesh mesh, Color albedo, const std::string& name) {
  return place(std::move(mesh), Transform{}, albedo, name);
}

void add_box(Scene& s, const glm::vec3& min, const glm::vec3& max, Color albedo,
             const std::string& name) {
  s.meshes.push_back(place(make_box(min, max), albedo, name));
}

void add_pieces(Scene& s, std::vector<Mesh> pieces, Color albedo) {
  for (Mesh& piece : pieces) {
    const std::string name = piece.name;  // before the mesh moves
    s.meshes.push_back(place(std::move(piece), albedo, name));
  }
}

Light spot(glm::vec3 position, glm::vec3 target, Color intensity, float cone_deg, float edge_deg) {
  Light light;
  light.type = LightType::spot;
  light.position = position;
  light.direction = glm::normalize(target - position);
  light.intensity = intensity;
  light.cone_deg = cone_deg;
  light.edge_deg = edge_deg;
  light.gobo_up = scene_light::default_gobo_up(light.direction);
  return light;
}

Phase single_lobe(PhaseType type, float g) { return Phase{{PhaseLobe{type, g, 1.0f}}}; }

Mesh floor_slab(float half_size, Color albedo) {
  return place(make_box({-half_size, -0.2f, -half_size}, {half_size, 0.0f, half_size}), albedo,
               "floor");
}

Beam beam_through(const Light& sun, const Extent& opening, const Extent& room, float margin) {
  const glm::vec3 d = sun.direction, centre = 0.5f * (opening.min + opening.max);
  const glm::vec3 right = glm::normalize(glm::cross(d, sun.gobo_up)), up = glm::cross(right, d);
  float upstream = 0.0f;
  glm::vec2 half(0.0f);
  for (const glm::vec3& c : corners(opening)) {
    upstream = std::max(upstream, glm::dot(centre - c, d));
    half = glm::max(half, glm::abs(glm::vec2(glm::dot(c - centre, right), glm::dot(c - centre, up))));
  }
  Beam beam;
  beam.origin = centre - (upstream + margin) * d;
  beam.size = 2.0f * (half + margin);
  for (const glm::vec3& c : corners(room))
    beam.length = std::max(beam.length, glm::dot(c - beam.origin, d) + margin);
  return beam;
}

}  // namespace airlight::scene_builtin
