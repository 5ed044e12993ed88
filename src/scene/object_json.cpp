// "objects" entries (docs/design.md §4). Every object has the optional keys
//   translate [x,y,z], rotate_deg [rx,ry,rz] (about world X, then Y, then Z),
//   scale s (> 0, uniform), albedo (colour in [0,1], default 0.7), name,
//   casts_shadows (true or false, default true: whether it shadows the lights),
//   outer_box {min, max} (encloses every vertex), inner_box {min, max} (inside the mesh, which
//   must be closed once welded by exact position): Nilsson §5.1's bounding volumes, in the
//   object's own coordinates before its transform, which then carries them (oriented boxes);
// and either "mesh": "file.obj" or "shape" with the shape's keys:
//   box       min, max
//   sphere    radius; center [0,0,0]; segments 48 (around; segments/2 rings)
//   plane     size [sx, sz]; center [0,0,0]; normal [0,1,0]
//   cylinder  radius, height (along +y); base [0,0,0] (centre of the bottom cap); segments 48
//   teapot    segments 8 (quads per patch edge); 1 unit tall on y = 0 at scale 1
#include "core/solid.hpp"
#include "scene/mesh_build.hpp"
#include "scene/scene_parse.hpp"
#include "scene/shapes.hpp"

#include <cmath>
#include <glm/vector_relational.hpp>
#include <map>

namespace airlight::scene_json {
namespace {

using namespace scene_mesh;

// The axis-aligned box of a "min" and a "max", as a box shape and a bounding volume give it.
OrientedBox read_min_max(JsonObject& o) {
  const auto [min_node, max_node] = o.required_all({"min", "max"});
  const glm::vec3 min = min_node.vec3(), max = max_node.vec3();
  if (!glm::all(glm::lessThan(min, max))) o.fail("max", "must exceed min on every axis");
  return OrientedBox{0.5f * (min + max), glm::mat3(1.0f), 0.5f * (max - min)};
}

Mesh read_box(JsonObject& o) {
  const OrientedBox box = read_min_max(o);
  return make_box(box.center - box.half, box.center + box.half);
}

Mesh read_sphere(JsonObject& o) {
  const glm::vec3 center = o.vec3_or("center", glm::vec3(0.0f));
  const float radius = o.required("radius").number(greater_than(0));
  return make_sphere(center, radius, o.integer_or("segments", 4, 1024, 48));
}

Mesh read_plane(JsonObject& o) {
  const glm::vec3 center = o.vec3_or("center", glm::vec3(0.0f));
  const glm::vec2 size = o.required("size").vec2(greater_than(0));
  const auto normal = o.optional("normal");
  return make_plane(center, size, normal ? normal->direction() : glm::vec3(0, 1, 0));
}

Mesh read_cylinder(JsonObject& o) {
  const glm::vec3 base = o.vec3_or("base", glm::vec3(0.0f));
  const auto [radius, height] = o.required_all({"radius", "height"});
  const float r = radius.number(greater_than(0)), h = height.number(greater_than(0));
  return make_cylinder(base, r, h, o.integer_or("segments", 3, 1024, 48));
}

Mesh read_teapot(JsonObject& o) { return make_teapot(o.integer_or("segments", 2, 64, 8)); }

Mesh read_shape(JsonObject& o) {
  using Reader = Mesh (*)(JsonObject&);
  static const std::map<std::string, Reader> readers = {{"box", read_box},
                                                        {"sphere", read_sphere},
                                                        {"plane", read_plane},
                                                        {"cylinder", read_cylinder},
                                                        {"teapot", read_teapot}};
  const JsonNode shape = o.required("shape");
  const auto it = readers.find(shape.string());
  if (it == readers.end()) shape.fail("must be box, sphere, plane, cylinder or teapot");
  return it->second(o);
}

Mesh read_mesh_file(JsonObject& o, const SceneFiles& files) {
  const JsonNode mesh = o.required("mesh");
  const std::filesystem::path file = files.dir / mesh.string();
  if (!files.source.exists(file)) mesh.fail("file not found: " + file.string());
  return load_obj(file, files.source);
}

Transform read_transform(JsonObject& o) {
  Transform t;
  t.translate = o.vec3_or("translate", t.translate);
  t.rotate_deg = o.vec3_or("rotate_deg", t.rotate_deg);
  t.scale = o.number_or("scale", greater_than(0), t.scale);
  return t;
}

// An object's bounding volume (Nilsson §5.1), checked against its mesh in the object's own
// coordinates, where the box is axis-aligned and nothing has been rounded by the transform.
std::optional<OrientedBox> read_bounding_box(JsonObject& o, std::string_view name,
                                             void (*check)(const Mesh&, const OrientedBox&,
                                                           const JsonNode&),
                                             const Mesh& mesh) {
  const auto node = o.optional(name);
  if (!node) return std::nullopt;
  JsonObject b(*node);
  const OrientedBox box = read_min_max(b);
  b.finish();
  check(mesh, box, *node);
  return box;
}

void check_outer(const Mesh& mesh, const OrientedBox& box, const JsonNode& node) {
  for (const glm::vec3& p : mesh.positions)
    if (glm::any(glm::greaterThan(glm::abs(p - box.center), box.half)))
      node.fail("does not enclose the object");
}

void check_inner(const Mesh& mesh, const OrientedBox& box, const JsonNode& node) {
  if (!solid::closed(mesh.positions, mesh.triangles)) node.fail("an open mesh has no inside");
  if (!solid::box_inside(mesh.positions, mesh.triangles, box)) node.fail("is not inside the object");
}

// Extreme sizes and transforms can overflow or collapse float geometry.
void check_placed(const Mesh& mesh, const JsonNode& node) {
  if (mesh.triangles.empty()) node.fail("is too small to make any triangle");
  for (const glm::vec3& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      node.fail("its transform makes coordinates non-finite");
  for (const glm::uvec3& t : mesh.triangles)
    if (is_degenerate(mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]))
      node.fail("its transform collapses triangles to zero area");
}

}  // namespace

Mesh read_object(const JsonNode& node, const SceneFiles& files) {
  JsonObject o(node);
  if (o.has("shape") == o.has("mesh")) node.fail("needs exactly one of \"shape\" and \"mesh\"");
  Mesh mesh = o.has("shape") ? read_shape(o) : read_mesh_file(o, files);
  mesh.outer_box = read_bounding_box(o, "outer_box", check_outer, mesh);
  mesh.inner_box = read_bounding_box(o, "inner_box", check_inner, mesh);
  const Transform transform = read_transform(o);
  mesh.albedo = o.color_or("albedo", closed(0, 1), mesh.albedo);
  mesh.casts_shadows = o.boolean_or("casts_shadows", true);
  const auto name = o.optional("name");
  const std::string label = name ? name->string() : mesh.name;
  o.finish();
  apply(transform, mesh);
  check_placed(mesh, node);
  mesh.name = node.key() + " (" + label + ")";
  return mesh;
}

}  // namespace airlight::scene_json
