// Seeded random scenes (random_scene.hpp). A scene is drawn in three steps: its
// structure from the seed's group, then sizes, media, lights, casters and camera
// from the seed, in units of the scene's size L; then one special case may be
// forced by moving the camera, a light or a caster; last the cases the scene
// has are found geometrically, whatever was forced.
#include "harness/random_scene.hpp"

#include "core/solid.hpp"
#include "geometry/camera.hpp"
#include "geometry/segment_box.hpp"
#include "harness/random.hpp"
#include "optics/light.hpp"
#include "scene/gobo_patterns.hpp"
#include "scene/light_defaults.hpp"
#include "scene/mesh_build.hpp"
#include "scene/shapes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

namespace airlight::harness {
namespace {

using glm::dvec3;

// ---- structure: what the shader defines see (methods/kit/frame/scene_defines.cpp) ----

enum class Space { room, ground, open };
enum class CasterKind { box, sphere, cylinder, teapot, polyhedron, open_mesh, quad };
constexpr std::array kCasterKinds{CasterKind::box,        CasterKind::sphere,    CasterKind::cylinder, CasterKind::teapot,
                                  CasterKind::polyhedron, CasterKind::open_mesh, CasterKind::quad};
constexpr std::array kCasterNames{"box", "sphere", "cylinder", "teapot", "polyhedron", "open_mesh", "quad"};
constexpr std::array kPhaseTypes{PhaseType::isotropic, PhaseType::rayleigh, PhaseType::henyey_greenstein,
                                 PhaseType::schlick,   PhaseType::hazy,     PhaseType::murky};
constexpr std::array kLightTypes{LightType::point, LightType::spot, LightType::directional};

// A light's structure: its type and the kit's per-light defines — shadow kind
// (a spot's cone from 60° on takes a cube map, shadow_projection.hpp), smooth
// edge, gobo, beam.
struct LightShape {
  LightType type = LightType::point;
  bool wide = false, edge = false, gobo = false, beam = false;
};

struct Structure {
  Space space = Space::open;
  std::vector<CasterKind> casters;
  std::vector<bool> casts_shadows;
  std::vector<LightShape> lights;
  std::vector<std::vector<PhaseType>> phases;  // the medium's lobes, then each volume's
  LightModelType model = LightModelType::physical;
  bool grey = true;
  std::uint64_t hash = 0xcbf29ce484222325ull;  // FNV-1a over every choice, in the order drawn

  int note(int choice) {
    hash = (hash ^ static_cast<std::uint64_t>(choice)) * 0x100000001b3ull;
    return choice;
  }
  bool note(bool choice) { return note(int(choice)) != 0; }
};

// Stream 1 of the group's seed: apart from the placements' stream 0, so seed 1's
// placements do not repeat group 1's structure draws.
Structure draw_structure(std::uint64_t group) {
  Random r(group, 1);
  Structure s;
  const double space = r.uniform();
  s.space = static_cast<Space>(s.note(space < 0.55 ? 0 : space < 0.85 ? 1 : 2));
  const int casters = s.note(r.integer(0, 6));
  for (int k = 0; k < casters; ++k) {
    s.casters.push_back(kCasterKinds[static_cast<size_t>(s.note(r.integer(0, int(kCasterKinds.size()) - 1)))]);
    s.casts_shadows.push_back(s.note(r.bernoulli(0.8)));
  }
  const int lights = s.note(r.bernoulli(0.08) ? 0 : r.integer(1, 5));  // few dark scenes: they force fewer cases
  for (int k = 0; k < lights; ++k) {
    LightShape l;
    l.type = kLightTypes[static_cast<size_t>(s.note(r.integer(0, 2)))];
    if (l.type == LightType::spot) {
      l.wide = s.note(r.bernoulli(0.3));
      l.edge = s.note(r.bernoulli(0.5));
      l.gobo = s.note(r.bernoulli(0.3));
    } else if (l.type == LightType::directional) {
      l.beam = s.note(r.bernoulli(0.5));
      l.gobo = s.note(l.beam && r.bernoulli(0.4));
    }
    s.lights.push_back(l);
  }
  const int volumes = s.note(r.bernoulli(0.6) ? r.integer(1, 2) : 0);
  for (int m = 0; m <= volumes; ++m) {
    const int lobes = s.note(r.bernoulli(0.5) ? 1 : r.integer(2, 3));
    std::vector<PhaseType> types;
    for (int k = 0; k < lobes; ++k) types.push_back(kPhaseTypes[static_cast<size_t>(s.note(r.integer(0, 5)))]);
    s.phases.push_back(types);
  }
  s.model = s.note(r.bernoulli(0.1)) ? LightModelType::simplified : LightModelType::physical;
  s.grey = s.note(r.bernoulli(0.4));
  return s;
}

// ---- continuous draws ---------------------------------------------------------

struct Box3 {
  dvec3 min, max;
  dvec3 size() const { return max - min; }
  double diagonal() const { return glm::length(size()); }
  bool contains(const dvec3& p) const {
    return glm::all(glm::greaterThan(p, min)) && glm::all(glm::lessThan(p, max));
  }
};

Box3 bounds_of(const std::vector<glm::vec3>& points) {
  Box3 b{dvec3(INFINITY), dvec3(-INFINITY)};
  for (const glm::vec3& p : points) b.min = glm::min(b.min, dvec3(p)), b.max = glm::max(b.max, dvec3(p));
  return b;
}

dvec3 point_in(Random& r, const Box3& b, double margin) {
  dvec3 p;
  for (int i = 0; i < 3; ++i) p[i] = r.uniform(b.min[i] + margin * b.size()[i], b.max[i] - margin * b.size()[i]);
  return p;
}

// Three draws in [lo, hi), one per statement (random.hpp).
dvec3 uniform3(Random& r, double lo, double hi) {
  const double x = r.uniform(lo, hi);
  const double y = r.uniform(lo, hi);
  const double z = r.uniform(lo, hi);
  return {x, y, z};
}

Color tint(Random& r, bool grey, double lo) { return grey ? Color(1.0f) : Color(uniform3(r, lo, 1.0)); }

Phase draw_phase(Random& r, const std::vector<PhaseType>& types) {
  Phase phase;
  phase.lobes.clear();
  float total = 0.0f;
  for (const PhaseType type : types) {
    const bool has_g = type == PhaseType::henyey_greenstein || type == PhaseType::schlick;
    const float g = has_g ? float(r.uniform(-0.95, 0.95)) : 0.0f;
    phase.lobes.push_back({type, g, float(r.uniform(0.1, 1.0))});
    total += phase.lobes.back().weight;
  }
  float rest = 1.0f;
  for (size_t k = 0; k + 1 < phase.lobes.size(); ++k) rest -= (phase.lobes[k].weight /= total);
  phase.lobes.back().weight = std::max(rest, 0.0f);  // the last takes what rounding left: the sum is 1
  return phase;
}

// Per-vertex normals as the area-weighted sum of the faces around each vertex:
// for the meshes built here by moving vertices.
void smooth_normals(Mesh& mesh) {
  std::vector<dvec3> sums(mesh.positions.size(), dvec3(0.0));
  for (const glm::uvec3& t : mesh.triangles) {
    const dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    const dvec3 n = glm::cross(b - a, c - a);
    for (int i = 0; i < 3; ++i) sums[t[i]] += n;
  }
  for (size_t v = 0; v < sums.size(); ++v) mesh.normals[v] = glm::vec3(glm::normalize(sums[v]));
}

// A caster of `size` about the origin, before its rotation and placement.
Mesh caster_mesh(Random& r, CasterKind kind, float size) {
  using namespace scene_mesh;
  switch (kind) {
    case CasterKind::box: {
      const glm::vec3 half = size * glm::vec3(uniform3(r, 0.3, 1.0));
      return make_box(-half, half);
    }
    case CasterKind::sphere: return make_sphere(glm::vec3(0.0f), size, r.integer(6, 24));
    case CasterKind::cylinder: {
      const float radius = size * float(r.uniform(0.2, 0.8));
      const float height = 2.0f * size * float(r.uniform(0.3, 1));
      return make_cylinder({0, -size, 0}, radius, height, r.integer(6, 24));
    }
    case CasterKind::teapot: {
      Mesh teapot = make_teapot(3);  // 576 triangles: the detection and the reference stay fast
      apply(Transform{glm::vec3(0, -0.5f * size, 0), glm::vec3(0.0f), size}, teapot);
      return teapot;
    }
    case CasterKind::polyhedron: {  // a coarse sphere with its vertices moved in and out: closed, not convex
      Mesh mesh = make_sphere(glm::vec3(0.0f), size, r.integer(4, 8));
      for (glm::vec3& p : mesh.positions) p *= float(r.uniform(0.6, 1.4));
      smooth_normals(mesh);
      mesh.name = "polyhedron";
      return mesh;
    }
    case CasterKind::open_mesh: {  // a bumpy height field: open, its edges a boundary
      const int n = r.integer(2, 5);
      MeshBuilder b;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
          b.vertex({size * (2.0f * i / n - 1), size * float(r.uniform(-0.3, 0.3)), size * (2.0f * j / n - 1)},
                   {0, 1, 0});
      const auto at = [n](int i, int j) { return static_cast<uint32_t>(i * (n + 1) + j); };
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) b.quad(at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
      Mesh mesh = b.take("open_mesh");
      smooth_normals(mesh);
      return mesh;
    }
    case CasterKind::quad: {
      const glm::vec2 sides(uniform3(r, 0.3, 1.0));
      return make_plane(glm::vec3(0.0f), 2.0f * size * sides, glm::vec3(r.unit_vector()));
    }
  }
  return {};
}

// A room: the box's faces turned inward, so that the walls end every view ray.
Mesh room_mesh(const Box3& box) {
  Mesh mesh = scene_mesh::make_box(glm::vec3(box.min), glm::vec3(box.max));
  for (glm::uvec3& t : mesh.triangles) std::swap(t.y, t.z);
  for (glm::vec3& n : mesh.normals) n = -n;
  return mesh;
}

// What random_scene draws before the special case and the enclosure's mesh.
struct Draft {
  Random r;
  Structure structure;
  double size = 1.0;  // L
  Box3 box{};  // the room, or the region the lights, casters and camera are drawn in
  double far_near = 10.0;
  Scene scene{};
};

double mean(const Color& c) { return (double(c.r) + double(c.g) + double(c.b)) / 3.0; }

// The scales that keep L_air of order 1 at the eye: a point light at distance r
// from the eye gives about σs·I/(4 r) along a ray passing it at that distance,
// dimmed by exp(−σt·r) on the way (capped so that I stays a float).
double dimming(const Draft& d, double distance) {
  if (d.scene.light_model.type == LightModelType::simplified) return 1.0;  // T = 1
  return std::exp(std::min(mean(d.scene.medium.sigma_t()) * distance, 40.0));
}

void scale_light(Draft& d, Light& light, double k) {
  const double sigma_s = mean(d.scene.medium.sigma_s), sigma_t = mean(d.scene.medium.sigma_t());
  const Color color = tint(d.r, d.structure.grey, 0.3);
  if (light.type == LightType::directional) {
    // σs·E·ℓ/(4π) over the stretch ℓ that the fog lets the eye see, or the beam's width.
    double reach = std::min(d.box.diagonal(), 1.0 / sigma_t);
    double from = 0.0;
    if (light.beam) {
      reach = std::min(reach, double(std::min(light.beam->size.x, light.beam->size.y)));
      from = glm::distance(dvec3(d.scene.camera.position), dvec3(light.beam->origin));
    }
    light.irradiance = color * float(k * 4.0 * std::numbers::pi / (sigma_s * reach) * dimming(d, from));
  } else {
    const double r = glm::distance(dvec3(d.scene.camera.position), dvec3(light.position));
    light.intensity = color * float(k * 4.0 * std::max(r, 1e-3 * d.size) / sigma_s * dimming(d, r));
  }
}

glm::vec3 gobo_up(Random& r, const glm::vec3& direction) {
  const glm::vec3 up(r.unit_vector());
  return scene_light::parallel(up, direction) ? scene_light::default_gobo_up(direction) : up;
}

std::shared_ptr<const Image> gobo(Random& r) {
  if (r.bernoulli(0.5)) return std::make_shared<const Image>(scene_gobo::stained_glass(16, 24));
  const int grid = r.integer(2, 5);
  return std::make_shared<const Image>(scene_gobo::polka_dots(16, grid, float(r.uniform(0.3, 0.9))));
}

Light draw_light(Draft& d, const LightShape& shape) {
  Random& r = d.r;
  Light light;
  light.type = shape.type;
  if (shape.type == LightType::directional) {
    dvec3 dir = r.unit_vector();
    dir.y = -std::abs(dir.y) - 0.2;  // from above, mostly
    light.direction = glm::vec3(glm::normalize(dir));
    if (shape.beam) {
      const dvec3 target = point_in(r, d.box, 0.1);
      const double back = d.box.diagonal() * r.uniform(0.3, 1.0);
      const glm::vec2 size(d.size * uniform3(r, 0.1, 0.6));
      const double length = d.box.diagonal() * r.uniform(1.0, 2.5);
      light.beam = Beam{glm::vec3(target - back * dvec3(light.direction)), size, float(length)};
      light.gobo_up = gobo_up(r, light.direction);
      if (shape.gobo) light.gobo = gobo(r);
    }
  } else {
    const dvec3 position = point_in(r, d.box, 0.02);
    light.position = glm::vec3(position);
    if (shape.type == LightType::spot) {
      dvec3 axis = point_in(r, d.box, 0.0) - position;
      if (!(glm::length(axis) > 1e-3 * d.size)) axis = dvec3(0, -1, 0);
      light.direction = glm::vec3(glm::normalize(axis));
      light.cone_deg = float(shape.wide ? r.uniform(60.0, shape.gobo ? 89.0 : 179.0) : r.uniform(5.0, 59.0));
      light.edge_deg = shape.edge ? light.cone_deg * float(r.uniform(0.05, 1.0)) : 0.0f;
      light.gobo_up = gobo_up(r, light.direction);
      if (shape.gobo) light.gobo = gobo(r);
    }
  }
  return light;
}

// World up, or +z for a view straight up or down.
glm::vec3 up_for(const Camera& c) { return scene_light::default_gobo_up(c.look_at - c.position); }

Camera draw_camera(Draft& d) {
  Random& r = d.r;
  Camera c;
  c.position = glm::vec3(point_in(r, d.box, 0.05));
  do c.look_at = glm::vec3(point_in(r, d.box, 0.0));
  while (!(glm::distance(c.position, c.look_at) > 0.1f * float(d.size)));
  c.up = up_for(c);
  c.fov_y_deg = float(r.uniform(20.0, 100.0));
  // Far covers the scene from wherever the eye is, or now and then cuts it.
  c.far = float(d.box.diagonal() * (r.bernoulli(0.15) ? r.uniform(0.2, 0.9) : r.uniform(1.0, 2.0)));
  d.far_near = r.log_uniform(10.0, 0.99 * max_far_over_near);  // a hair inside: far/near is checked in float
  c.near = float(c.far / d.far_near);
  return c;
}

// ---- geometry of the special cases ---------------------------------------------

bool is_caster(const Mesh& mesh) { return !is_enclosure(mesh); }
bool is_shadow_caster(const Mesh& mesh) { return is_caster(mesh) && mesh.casts_shadows; }
bool positional(const Light& light) { return light.type != LightType::directional; }

Box3 mesh_box(const Mesh& mesh) { return bounds_of(mesh.positions); }

// Whether the open segment from p to q crosses a triangle of the mesh (Möller–
// Trumbore); its ends are left out by a hair, so that an eye or a light on a
// surface does not count as behind it.
bool segment_hits(const Mesh& mesh, const dvec3& p, const dvec3& q) {
  const Box3 box = mesh_box(mesh);
  if (!geometry::segment_meets_box(p, q - p, box.min, box.max)) return false;
  const dvec3 d = q - p;
  for (const glm::uvec3& t : mesh.triangles) {
    const dvec3 a(mesh.positions[t.x]), e1 = dvec3(mesh.positions[t.y]) - a, e2 = dvec3(mesh.positions[t.z]) - a;
    const dvec3 h = glm::cross(d, e2);
    const double det = glm::dot(e1, h);
    if (det == 0.0) continue;
    const dvec3 s = (p - a) / det;
    const double u = glm::dot(s, h);
    if (u < 0.0 || u > 1.0) continue;
    const dvec3 qv = glm::cross(s, e1);
    const double v = glm::dot(d, qv);
    if (v < 0.0 || u + v > 1.0) continue;
    const double at = glm::dot(e2, qv);
    if (at > 1e-9 && at < 1.0 - 1e-9) return true;
  }
  return false;
}

// Where a light's ray toward the eye starts: the light itself, or for a
// directional light a point upstream past everything in the mesh's box.
dvec3 light_source_for(const Light& light, const dvec3& eye, const Box3& box) {
  if (positional(light)) return dvec3(light.position);
  const double reach = glm::distance(eye, 0.5 * (box.min + box.max)) + box.diagonal();
  return eye - 2.0 * reach * dvec3(light.direction);
}

bool eye_in_shadow(const Scene& scene) {
  const dvec3 eye(scene.camera.position);
  for (const Light& light : scene.lights)
    for (const Mesh& mesh : scene.meshes)
      if (is_shadow_caster(mesh) && segment_hits(mesh, eye, light_source_for(light, eye, mesh_box(mesh)))) return true;
  return false;
}

// Inside a spot's cone (its smooth edge included) or a beam's box.
bool lights_point(const Light& light, const dvec3& p) {
  if (light.type == LightType::spot) {
    const dvec3 to = p - dvec3(light.position);
    return glm::length(to) > 0.0 && optics::spot_cone(light, glm::normalize(to)) > 0.0;
  }
  if (light.type == LightType::directional) return !light.beam || optics::inside_beam(light, p);
  return true;
}

bool eye_in_cone(const Scene& scene) {
  const dvec3 eye(scene.camera.position);
  for (const Light& light : scene.lights)
    if ((light.type == LightType::spot || optics::has_beam(light)) && lights_point(light, eye)) return true;
  return false;
}

bool eye_in_volume(const Scene& scene) {
  for (const Volume& v : scene.volumes)
    if (Box3{dvec3(v.min), dvec3(v.max)}.contains(dvec3(scene.camera.position))) return true;
  return false;
}

// A mesh's edges welded by exact position, each with the triangles that share
// it (second = −1: an open mesh's border). Sorted vectors, not maps: every
// scene's detection builds them for every caster.
struct SharedEdge {
  dvec3 a, b;
  int first = 0, second = -1;
};

std::vector<SharedEdge> shared_edges(const Mesh& mesh) {
  std::vector<uint32_t> order(mesh.positions.size());
  for (uint32_t v = 0; v < order.size(); ++v) order[v] = v;
  const auto key = [&](uint32_t v) {
    const glm::vec3& p = mesh.positions[v];
    return std::array<float, 3>{p.x + 0.0f, p.y + 0.0f, p.z + 0.0f};  // +0.0f: −0 and +0 are one position
  };
  std::ranges::sort(order, [&](uint32_t u, uint32_t v) { return key(u) < key(v); });
  std::vector<uint32_t> id(order.size());
  for (size_t k = 0, next = 0; k < order.size(); ++k) {
    if (k > 0 && key(order[k]) != key(order[k - 1])) ++next;
    id[order[k]] = static_cast<uint32_t>(next);
  }
  struct Side {
    std::pair<uint32_t, uint32_t> welded;
    int triangle;
    uint32_t from, to;
  };
  std::vector<Side> sides;
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t i = mesh.triangles[t][k], j = mesh.triangles[t][(k + 1) % 3];
      sides.push_back({std::minmax(id[i], id[j]), static_cast<int>(t), i, j});
    }
  std::ranges::stable_sort(sides, [](const Side& x, const Side& y) { return x.welded < y.welded; });
  std::vector<SharedEdge> edges;
  for (size_t k = 0; k < sides.size();) {
    size_t end = k + 1;
    while (end < sides.size() && sides[end].welded == sides[k].welded) ++end;
    if (end - k <= 2)  // more than two triangles on an edge: no silhouette to speak of
      edges.push_back({dvec3(mesh.positions[sides[k].from]), dvec3(mesh.positions[sides[k].to]), sides[k].triangle,
                       end - k == 2 ? sides[k + 1].triangle : -1});
    k = end;
  }
  return edges;
}

struct Edge {
  dvec3 a, b;
};

// The silhouette edges of a mesh from a light: an open mesh's border, and the
// edges between a triangle facing the light and one that does not.
std::vector<Edge> silhouette_edges(const Mesh& mesh, const std::vector<SharedEdge>& shared, const Light& light) {
  std::vector<bool> facing(mesh.triangles.size());
  for (size_t t = 0; t < facing.size(); ++t) {
    const glm::uvec3& i = mesh.triangles[t];
    const dvec3 a(mesh.positions[i.x]), b(mesh.positions[i.y]), c(mesh.positions[i.z]);
    const dvec3 to_light = positional(light) ? dvec3(light.position) - a : -dvec3(light.direction);
    facing[t] = glm::dot(glm::cross(b - a, c - a), to_light) > 0.0;
  }
  std::vector<Edge> edges;
  for (const SharedEdge& e : shared)
    if (e.second < 0 || facing[size_t(e.first)] != facing[size_t(e.second)]) edges.push_back({e.a, e.b});
  return edges;
}

// How far off a shadow side's plane the eye may be and still be on it: what
// placing it there in float coordinates leaves (about 10⁻⁷ of them), with room.
constexpr double kOnPlane = 1e-5;

// Whether the eye is on the shadow's side swept from edge ab away from the light.
bool on_shadow_side(const Light& light, const Edge& e, const dvec3& eye) {
  if (positional(light)) {
    const dvec3 l(light.position), u = e.a - l, v = e.b - l, w = eye - l;
    const dvec3 n = glm::cross(u, v);
    if (!(glm::length(n) > 0.0) || std::abs(glm::dot(w, glm::normalize(n))) > kOnPlane * glm::length(w)) return false;
    // w = α·u + β·v in the plane: beyond the edge from the light when α, β ≥ 0 and α + β ≥ 1.
    const double uu = glm::dot(u, u), uv = glm::dot(u, v), vv = glm::dot(v, v), det = uu * vv - uv * uv;
    const double alpha = (glm::dot(w, u) * vv - glm::dot(w, v) * uv) / det;
    const double beta = (glm::dot(w, v) * uu - glm::dot(w, u) * uv) / det;
    return alpha >= 0.0 && beta >= 0.0 && alpha + beta >= 1.0;
  }
  const dvec3 u = e.b - e.a, d(light.direction), w = eye - e.a;
  const dvec3 n = glm::cross(u, d);
  if (!(glm::length(n) > 0.0) || std::abs(glm::dot(w, glm::normalize(n))) > kOnPlane * glm::length(w)) return false;
  // w = s·u + t·d: along the edge and downstream of it.
  const double uu = glm::dot(u, u), ud = glm::dot(u, d), dd = glm::dot(d, d), det = uu * dd - ud * ud;
  const double s = (glm::dot(w, u) * dd - glm::dot(w, d) * ud) / det;
  const double t = (glm::dot(w, d) * uu - glm::dot(w, u) * ud) / det;
  return s >= 0.0 && s <= 1.0 && t >= 0.0;
}

bool eye_on_shadow_plane(const Scene& scene) {
  const dvec3 eye(scene.camera.position);
  for (const Mesh& mesh : scene.meshes) {
    if (!is_shadow_caster(mesh) || scene.lights.empty()) continue;
    const std::vector<SharedEdge> shared = shared_edges(mesh);
    for (const Light& light : scene.lights)
      for (const Edge& e : silhouette_edges(mesh, shared, light))
        if (on_shadow_side(light, e, eye)) return true;
  }
  return false;
}

// In the image of any width ≥ height: inside the vertical field of view on both axes.
bool in_image(const Camera& camera, const dvec3& p) {
  const geometry::CameraBasis basis = geometry::camera_basis(camera);
  const dvec3 w = p - basis.position;
  const double z = glm::dot(w, basis.forward), reach = z * basis.tan_half_fov_y;
  return z > camera.near && z < camera.far && std::abs(glm::dot(w, basis.right)) <= reach &&
         std::abs(glm::dot(w, basis.up)) <= reach;
}

bool light_in_view(const Scene& scene) {
  for (const Light& light : scene.lights)
    if (positional(light) && in_image(scene.camera, dvec3(light.position))) return true;
  return false;
}

bool light_in_caster(const Scene& scene) {
  for (const Light& light : scene.lights)
    if (positional(light))
      for (const Mesh& mesh : scene.meshes)
        if (is_shadow_caster(mesh) && mesh_box(mesh).contains(dvec3(light.position))) return true;
  return false;
}

// The scene's size L: the box around the eye and what it looks at, the lights,
// the casters and a room (a ground is as large as far makes it).
double scene_scale(const Scene& scene) {
  std::vector<glm::vec3> points{scene.camera.position, scene.camera.look_at};
  for (const Light& light : scene.lights)
    if (positional(light)) points.push_back(light.position);
  for (const Mesh& mesh : scene.meshes)
    if (is_caster(mesh) || solid::closed(mesh.positions, mesh.triangles))
      for (const glm::vec3& p : mesh.positions) points.push_back(p);
  return bounds_of(points).diagonal();
}

// A hair of the scene: 10⁻⁴ L, where a light's own distance to a wall is of the
// order of a shadow map's depth bias and the counting methods' tolerances.
constexpr double kHair = 1e-4;

bool light_grazes_wall(const Scene& scene) {
  const double hair = kHair * scene_scale(scene);
  for (const Light& light : scene.lights) {
    if (!positional(light)) continue;
    const dvec3 p(light.position);
    for (const Mesh& mesh : scene.meshes) {
      if (!is_enclosure(mesh)) continue;
      for (const glm::uvec3& t : mesh.triangles) {
        const dvec3 a(mesh.positions[t.x]), e1 = dvec3(mesh.positions[t.y]) - a, e2 = dvec3(mesh.positions[t.z]) - a;
        const dvec3 n = glm::normalize(glm::cross(e1, e2));
        const double distance = glm::dot(p - a, n);
        if (std::abs(distance) > hair) continue;
        // The foot of the perpendicular inside the triangle, by barycentric coordinates.
        const dvec3 f = p - distance * n - a;
        const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
        const double d20 = glm::dot(f, e1), d21 = glm::dot(f, e2), det = d00 * d11 - d01 * d01;
        const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
        if (v >= 0.0 && w >= 0.0 && v + w <= 1.0) return true;
      }
    }
  }
  return false;
}

// The near plane's part in view (for any width ≥ height) as a box of no depth.
OrientedBox near_rectangle(const Camera& camera) {
  const geometry::CameraBasis b = geometry::camera_basis(camera);
  const double half = camera.near * b.tan_half_fov_y;
  return OrientedBox{glm::vec3(b.position + double(camera.near) * b.forward),
                     glm::mat3(glm::vec3(b.right), glm::vec3(b.up), glm::vec3(b.forward)),
                     glm::vec3(float(half), float(half), float(1e-6 * camera.near))};
}

// A caster crosses the near plane in view: a triangle meets the near
// rectangle, or the rectangle lies inside a closed caster.
bool caster_crosses_near(const Scene& scene) {
  const OrientedBox rect = near_rectangle(scene.camera);
  Box3 around{dvec3(INFINITY), dvec3(-INFINITY)};
  for (int k = 0; k < 8; ++k) around.min = glm::min(around.min, dvec3(rect.corner(k))), around.max = glm::max(around.max, dvec3(rect.corner(k)));
  for (const Mesh& mesh : scene.meshes) {
    if (!is_caster(mesh)) continue;
    const Box3 box = mesh_box(mesh);
    if (glm::any(glm::greaterThan(around.min, box.max)) || glm::any(glm::lessThan(around.max, box.min))) continue;
    for (const glm::uvec3& t : mesh.triangles)
      if (solid::crosses(rect, mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z])) return true;
    if (solid::closed(mesh.positions, mesh.triangles) &&
        solid::inside(mesh.positions, mesh.triangles, dvec3(rect.center)))
      return true;
  }
  return false;
}

// Whether the enclosure leaves p in view: inside a room, above a ground.
bool within_enclosure(const Scene& scene, const dvec3& p) {
  for (const Mesh& mesh : scene.meshes) {
    if (!is_enclosure(mesh)) continue;
    if (solid::closed(mesh.positions, mesh.triangles)) {
      if (!mesh_box(mesh).contains(p)) return false;
    } else if (glm::dot(p - dvec3(mesh.positions[0]), dvec3(mesh.normals[0])) <= 0.0) {
      return false;
    }
  }
  return true;
}

// The far plane cuts a light's lit region: a point of the far plane in view
// (a 9 × 9 grid over it) that the enclosure leaves visible lies in a light's
// cone, beam or everywhere-lit space. Casters are not asked: the region is
// the light's, as its bounds are before shadows.
bool far_cuts_light(const Scene& scene) {
  if (scene.lights.empty()) return false;
  const geometry::CameraBasis b = geometry::camera_basis(scene.camera);
  const double far = scene.camera.far, half = far * b.tan_half_fov_y;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      const dvec3 p = b.position + far * b.forward + half * ((i - 4) / 4.0 * b.right + (j - 4) / 4.0 * b.up);
      if (!within_enclosure(scene, p)) continue;
      for (const Light& light : scene.lights)
        if (lights_point(light, p)) return true;
    }
  return false;
}

// ---- forcing a special case ------------------------------------------------------
// Each moves the camera, a light or a caster of the draft so that the scene has
// the case; special_cases then checks that it does.

template <class T, class Keep>
std::vector<size_t> indices_of(const std::vector<T>& items, Keep keep) {
  std::vector<size_t> out;
  for (size_t i = 0; i < items.size(); ++i)
    if (keep(items[i])) out.push_back(i);
  return out;
}

size_t pick_index(Random& r, const std::vector<size_t>& indices) {
  return r.pick(std::span<const size_t>(indices));
}

// Moves the eye to the first of up to 8 candidates that is finite and inside the
// room (anywhere in an open scene), keeping a view direction.
void move_eye(Draft& d, const std::function<dvec3()>& candidate) {
  for (int attempt = 0; attempt < 8; ++attempt) {
    const dvec3 eye = candidate();
    if (!std::isfinite(eye.x + eye.y + eye.z) || (d.structure.space == Space::room && !d.box.contains(eye))) continue;
    Camera& c = d.scene.camera;
    c.position = glm::vec3(eye);
    if (!(glm::distance(c.position, c.look_at) > 0.05f * float(d.size)))
      c.look_at = glm::vec3(eye + 0.5 * d.size * d.r.unit_vector());
    c.up = up_for(c);
    return;
  }
}

// Looks at `target` with far at `depth` along the view, near following at the drawn far/near.
void look_at(Draft& d, const dvec3& target, double far) {
  Camera& c = d.scene.camera;
  if (!(glm::distance(dvec3(c.position), target) > 1e-3 * d.size)) return;
  c.look_at = glm::vec3(target);
  c.up = up_for(c);
  c.far = float(far);
  c.near = float(far / d.far_near);
}

const Light& any_light(Draft& d) {
  return d.scene.lights[static_cast<size_t>(d.r.integer(0, int(d.scene.lights.size()) - 1))];
}

const Mesh& any_shadow_caster(Draft& d) { return d.scene.meshes[pick_index(d.r, indices_of(d.scene.meshes, is_shadow_caster))]; }

// Past a caster's middle as seen from a light.
void force_eye_in_shadow(Draft& d) {
  move_eye(d, [&] {
    const Light& light = any_light(d);
    const Box3 box = mesh_box(any_shadow_caster(d));
    const dvec3 centre = 0.5 * (box.min + box.max);
    const dvec3 away = positional(light) ? glm::normalize(centre - dvec3(light.position)) : dvec3(light.direction);
    return centre + away * (0.5 * box.diagonal() * d.r.uniform(1.2, 2.5));
  });
}

void force_eye_in_cone(Draft& d) {
  const std::vector<size_t> aimed =
      indices_of(d.scene.lights, [](const Light& l) { return l.type == LightType::spot || optics::has_beam(l); });
  move_eye(d, [&] {
    const Light& light = d.scene.lights[pick_index(d.r, aimed)];
    dvec3 right, up;
    optics::gobo_frame(light, right, up);
    const dvec3 axis(light.direction);
    if (light.type == LightType::spot) {
      // Off the axis by up to 0.8 of the cone, toward a random side (tan alone: see random.hpp on sin and cos).
      const double off = std::tan(optics::radians(std::min(double(light.cone_deg), 89.0)) * d.r.uniform(0.0, 0.8));
      const dvec3 side = glm::normalize(glm::cross(axis, d.r.unit_vector()));
      const dvec3 dir = glm::normalize(axis + off * side);
      return dvec3(light.position) + dir * (d.size * d.r.uniform(0.1, 0.8));
    }
    const Beam& beam = *light.beam;
    const dvec3 at = uniform3(d.r, -0.4, 0.4) + dvec3(0.0, 0.0, 0.45);  // across the aperture, along the length
    return dvec3(beam.origin) + right * (beam.size.x * at.x) + up * (beam.size.y * at.y) + axis * (beam.length * at.z);
  });
}

void force_eye_in_volume(Draft& d) {
  move_eye(d, [&] {
    const Volume& v = d.scene.volumes[static_cast<size_t>(d.r.integer(0, int(d.scene.volumes.size()) - 1))];
    return point_in(d.r, Box3{dvec3(v.min), dvec3(v.max)}, 0.1);
  });
}

// On the shadow's side through a silhouette edge, a little past the edge.
void force_eye_on_shadow_plane(Draft& d) {
  move_eye(d, [&] {
    const Light& light = any_light(d);
    const Mesh& caster = any_shadow_caster(d);
    const std::vector<Edge> edges = silhouette_edges(caster, shared_edges(caster), light);
    if (edges.empty()) return dvec3(INFINITY);  // a light inside a closed caster may see none: no eye
    const Edge& e = d.r.pick(std::span<const Edge>(edges));
    const double share = d.r.uniform(0.1, 0.9);
    if (positional(light)) {
      const dvec3 l(light.position);
      return l + d.r.uniform(1.05, 1.5) * (share * (e.a - l) + (1.0 - share) * (e.b - l));
    }
    return e.a + share * (e.b - e.a) + dvec3(light.direction) * (d.size * d.r.uniform(0.02, 0.3));
  });
}

std::vector<size_t> positional_lights(const Scene& s) { return indices_of(s.lights, positional); }

void force_light_in_view(Draft& d) {
  const dvec3 target(d.scene.lights[pick_index(d.r, positional_lights(d.scene))].position);
  const Camera& c = d.scene.camera;
  const double distance = glm::distance(dvec3(c.position), target);
  // Off the centre by up to half the field of view; far past the light.
  const dvec3 off = d.r.unit_vector() * (0.5 * distance * std::tan(optics::radians(0.5 * c.fov_y_deg)));
  look_at(d, target + off, std::max(double(c.far), distance * d.r.uniform(1.2, 2.0)));
}

void force_light_in_caster(Draft& d) {
  Light& light = d.scene.lights[pick_index(d.r, positional_lights(d.scene))];
  light.position = glm::vec3(point_in(d.r, mesh_box(d.scene.meshes[pick_index(d.r, indices_of(d.scene.meshes, is_shadow_caster))]), 0.05));
}

// Within 10⁻⁷ to 10⁻⁵ L of a wall or the ground, inside: a hair (kHair) even
// of a scene drawn smaller than L, and above float's resolution of L.
void force_light_grazing(Draft& d) {
  Light& light = d.scene.lights[pick_index(d.r, positional_lights(d.scene))];
  const double gap = d.size * d.r.log_uniform(1e-7, 1e-5);
  const int axis = d.structure.space == Space::room ? d.r.integer(0, 2) : 1;
  const bool low = d.structure.space != Space::room || d.r.bernoulli(0.5);
  light.position[axis] = float(low ? d.box.min[axis] + gap : d.box.max[axis] - gap);
}

// A caster moved so that its nearest vertex along a view direction sits just
// before the near plane: the triangles there cross it in view.
void force_caster_across_near(Draft& d) {
  Mesh& mesh = d.scene.meshes[pick_index(d.r, indices_of(d.scene.meshes, is_caster))];
  const geometry::CameraBasis b = geometry::camera_basis(d.scene.camera);
  const double spread = 0.5 * b.tan_half_fov_y;
  const dvec3 off = uniform3(d.r, -spread, spread);
  const dvec3 w = glm::normalize(b.forward + off.x * b.right + off.y * b.up);
  const auto nearest = std::min_element(mesh.positions.begin(), mesh.positions.end(),
                                        [&](const glm::vec3& p, const glm::vec3& q) { return glm::dot(dvec3(p), w) < glm::dot(dvec3(q), w); });
  const double depth = d.scene.camera.near * d.r.uniform(0.5, 0.9);
  const glm::vec3 shift(b.position + w * (depth / glm::dot(w, b.forward)) - dvec3(*nearest));
  for (glm::vec3& p : mesh.positions) p += shift;
}

// Looks at a point the light lights, with far before it (a point light, on the
// way to it) or through it: the far plane's centre is then lit.
void force_far_cut(Draft& d) {
  Random& r = d.r;
  const Light& light = d.scene.lights[static_cast<size_t>(r.integer(0, int(d.scene.lights.size()) - 1))];
  const dvec3 eye(d.scene.camera.position);
  dvec3 target = point_in(r, d.box, 0.05);
  double before = 1.0;
  if (light.type == LightType::point) {
    target = dvec3(light.position);
    before = r.uniform(0.6, 0.95);
  } else if (light.type == LightType::spot || light.beam) {
    // Along the axis from the apex or the aperture's centre, where it is inside the box.
    const dvec3 from = light.type == LightType::spot ? dvec3(light.position) : dvec3(light.beam->origin);
    const dvec3 axis(light.direction);
    double t0 = 0.0, t1 = light.beam ? double(light.beam->length) : INFINITY;
    for (int i = 0; i < 3; ++i) {
      if (axis[i] == 0.0) continue;
      double a = (d.box.min[i] - from[i]) / axis[i], c = (d.box.max[i] - from[i]) / axis[i];
      if (a > c) std::swap(a, c);
      t0 = std::max(t0, a), t1 = std::min(t1, c);
    }
    if (!(t1 > t0)) return;
    target = from + axis * r.uniform(t0 + 0.1 * (t1 - t0), t1 - 0.1 * (t1 - t0));
  }
  look_at(d, target, before * glm::distance(eye, target));
}

void force(Draft& d, SpecialCase c) {
  switch (c) {
    case SpecialCase::camera_in_shadow: return force_eye_in_shadow(d);
    case SpecialCase::camera_in_cone: return force_eye_in_cone(d);
    case SpecialCase::camera_in_volume: return force_eye_in_volume(d);
    case SpecialCase::camera_on_shadow_plane: return force_eye_on_shadow_plane(d);
    case SpecialCase::light_on_view_ray: return force_light_in_view(d);
    case SpecialCase::light_in_caster_box: return force_light_in_caster(d);
    case SpecialCase::light_grazing_wall: return force_light_grazing(d);
    case SpecialCase::caster_across_near: return force_caster_across_near(d);
    case SpecialCase::far_cuts_lit_region: return force_far_cut(d);
  }
}

// The cases the draft has what it takes to force.
std::vector<SpecialCase> forceable(const Draft& d) {
  const Scene& s = d.scene;
  const bool lights = !s.lights.empty(), shadow_casters = std::ranges::any_of(s.meshes, is_shadow_caster);
  const bool spots = std::ranges::any_of(s.lights, positional);
  const bool aimed = std::ranges::any_of(s.lights, [](const Light& l) { return l.type == LightType::spot || optics::has_beam(l); });
  std::vector<SpecialCase> out;
  const auto add = [&](bool ok, SpecialCase c) {
    if (ok) out.push_back(c);
  };
  add(lights && shadow_casters, SpecialCase::camera_in_shadow);
  add(aimed, SpecialCase::camera_in_cone);
  add(!s.volumes.empty(), SpecialCase::camera_in_volume);
  add(lights && shadow_casters, SpecialCase::camera_on_shadow_plane);
  add(spots, SpecialCase::light_on_view_ray);
  add(spots && shadow_casters, SpecialCase::light_in_caster_box);
  add(spots && d.structure.space != Space::open, SpecialCase::light_grazing_wall);
  add(!s.meshes.empty(), SpecialCase::caster_across_near);
  add(lights, SpecialCase::far_cuts_lit_region);
  return out;
}

// ---- the draw ----------------------------------------------------------------------

Color unit_mean(const Color& c) { return c * (3.0f / (c.r + c.g + c.b)); }

void draw_media(Draft& d) {
  Random& r = d.r;
  const Structure& st = d.structure;
  Medium& m = d.scene.medium;
  const double sigma_t = r.log_uniform(1e-3, 20.0) / d.size, albedo = r.uniform(0.2, 1.0);
  m.sigma_s = unit_mean(tint(r, st.grey, 0.5)) * float(albedo * sigma_t);
  m.sigma_a = unit_mean(tint(r, st.grey, 0.5)) * float((1.0 - albedo) * sigma_t);
  m.phase = draw_phase(r, st.phases[0]);
  for (size_t v = 1; v < st.phases.size(); ++v) {
    Volume volume;
    const dvec3 centre = point_in(r, d.box, 0.1);
    const dvec3 half = d.size * uniform3(r, 0.05, 0.3);
    volume.min = glm::vec3(centre - half);
    volume.max = glm::vec3(centre + half);
    const double sigma = r.log_uniform(1e-2, 10.0) / (2.0 * (half.x + half.y + half.z) / 3.0), a = r.uniform(0.3, 1.0);
    volume.sigma_s = unit_mean(tint(r, st.grey, 0.3)) * float(a * sigma);
    volume.sigma_a = unit_mean(tint(r, st.grey, 0.3)) * float((1.0 - a) * sigma);
    volume.phase = draw_phase(r, st.phases[v]);
    d.scene.volumes.push_back(volume);
  }
  if (st.model == LightModelType::simplified)
    d.scene.light_model = {LightModelType::simplified, float(r.uniform(0.0, 0.1) * d.size * d.size), float(r.uniform(0.5, 2.0))};
}

void draw_casters(Draft& d) {
  Random& r = d.r;
  dvec3 centre(0.0);
  double size = 0.0;
  for (size_t k = 0; k < d.structure.casters.size(); ++k) {
    // Now and then inside or across the one before: nested and overlapping casters.
    if (k > 0 && r.bernoulli(0.25)) {
      centre += r.unit_vector() * (0.3 * size);
      size *= r.uniform(0.3, 1.0);
    } else {
      centre = point_in(r, d.box, 0.1);
      size = d.size * r.log_uniform(0.03, 0.3);
    }
    const CasterKind kind = d.structure.casters[k];
    Mesh mesh = caster_mesh(r, kind, float(size));
    const glm::vec3 turn(uniform3(r, 0.0, 360.0));
    scene_mesh::apply(scene_mesh::Transform{glm::vec3(centre), turn, 1.0f}, mesh);
    mesh.name = kCasterNames[static_cast<size_t>(kind)];
    mesh.albedo = tint(r, false, 0.2);
    mesh.casts_shadows = d.structure.casts_shadows[k];
    d.scene.meshes.push_back(std::move(mesh));
  }
}

// The room or the ground: last among the meshes, and casting no shadows, so that
// a sun or a beam reaches in and no method's bounding volumes take the room's
// inside for solid.
void add_enclosure(Draft& d) {
  if (d.structure.space == Space::open) return;
  Mesh mesh;
  if (d.structure.space == Space::room) {
    mesh = room_mesh(d.box);
  } else {  // as wide as far lets the eye see
    const float width = float(2.0 * (d.scene.camera.far + d.box.diagonal()));
    const dvec3 centre = 0.5 * (d.box.min + d.box.max);
    mesh = scene_mesh::make_plane(glm::vec3(centre.x, d.box.min.y, centre.z), {width, width}, {0, 1, 0});
  }
  mesh.name = enclosure_name;
  mesh.casts_shadows = false;
  d.scene.meshes.push_back(std::move(mesh));
}

}  // namespace

bool is_enclosure(const Mesh& mesh) {
  const std::string loaded = std::string(" (") + std::string(enclosure_name) + ")";  // the loader's "objects[i] (enclosure)"
  return mesh.name == enclosure_name || mesh.name.ends_with(loaded);
}

bool has_case(const Scene& scene, SpecialCase c) {
  switch (c) {
    case SpecialCase::camera_in_shadow: return eye_in_shadow(scene);
    case SpecialCase::camera_in_cone: return eye_in_cone(scene);
    case SpecialCase::camera_in_volume: return eye_in_volume(scene);
    case SpecialCase::camera_on_shadow_plane: return eye_on_shadow_plane(scene);
    case SpecialCase::light_on_view_ray: return light_in_view(scene);
    case SpecialCase::light_in_caster_box: return light_in_caster(scene);
    case SpecialCase::light_grazing_wall: return light_grazes_wall(scene);
    case SpecialCase::caster_across_near: return caster_crosses_near(scene);
    case SpecialCase::far_cuts_lit_region: return far_cuts_light(scene);
  }
  return false;
}

std::vector<SpecialCase> special_cases(const Scene& scene) {
  std::vector<SpecialCase> cases;
  for (int c = 0; c < special_case_count; ++c)
    if (has_case(scene, SpecialCase(c))) cases.push_back(SpecialCase(c));
  return cases;
}

std::string_view case_name(SpecialCase c) {
  static constexpr std::array<std::string_view, special_case_count> names{
      "camera_in_shadow",    "camera_in_cone",      "camera_in_volume",   "camera_on_shadow_plane", "light_on_view_ray",
      "light_in_caster_box", "light_grazing_wall", "caster_across_near", "far_cuts_lit_region"};
  return names[static_cast<size_t>(c)];
}

GeneratedScene random_scene(std::uint64_t seed) {
  Draft d{Random(seed), draw_structure(seed / structure_group)};
  Random& r = d.r;
  d.size = r.log_uniform(1e-3, 1e3);
  // The room, or the region of an open scene, somewhere within a few L of the origin.
  const dvec3 away = r.unit_vector();
  const dvec3 corner = away * (d.size * r.uniform(0.0, 2.0));
  const dvec3 extent = d.size * uniform3(r, 0.3, 1.0);
  d.box = {corner - 0.5 * dvec3(extent.x, 0.0, extent.z), corner + 0.5 * dvec3(extent.x, 2.0 * extent.y, extent.z)};
  d.scene.name = "random_" + std::to_string(seed);
  d.scene.camera = draw_camera(d);
  draw_media(d);
  for (const LightShape& shape : d.structure.lights) d.scene.lights.push_back(draw_light(d, shape));
  for (Light& light : d.scene.lights) scale_light(d, light, r.log_uniform(0.3, 3.0));
  draw_casters(d);
  // One case forced in every scene that can have one; the others come as drawn.
  if (const std::vector<SpecialCase> cases = forceable(d); !cases.empty())
    force(d, r.pick(std::span<const SpecialCase>(cases)));
  add_enclosure(d);
  GeneratedScene out{std::move(d.scene), {}, d.structure.hash, d.size};
  out.cases = special_cases(out.scene);
  return out;
}

std::vector<std::string> features(const Scene& scene) {
  std::vector<std::string> out;
  const auto add = [&](const std::string& f) {
    if (std::ranges::find(out, f) == out.end()) out.push_back(f);
  };
  static constexpr std::array light_names{"point", "spot", "directional"};
  for (const Light& l : scene.lights) {
    add(std::string("light:") + light_names[static_cast<size_t>(l.type)]);
    if (l.type == LightType::spot) {
      add(l.edge_deg > 0.0f ? "spot:smooth_edge" : "spot:hard_edge");
      if (l.cone_deg >= 60.0f) add("spot:wide");
      if (l.gobo) add("gobo:spot");
    }
    if (l.type == LightType::directional) add(l.beam ? "directional:beam" : "directional:unbounded");
    if (optics::has_beam(l) && l.gobo) add("gobo:beam");
  }
  static constexpr std::array phase_names{"isotropic", "rayleigh", "henyey_greenstein", "schlick", "hazy", "murky"};
  const auto phase = [&](const Phase& p) {
    for (const PhaseLobe& lobe : p.lobes) add(std::string("phase:") + phase_names[static_cast<size_t>(lobe.type)]);
    if (p.lobes.size() > 1) add("phase:sum");
  };
  phase(scene.medium.phase);
  for (const Volume& v : scene.volumes) phase(v.phase);
  if (!scene.volumes.empty()) add("volume");
  const auto grey = [](const Color& c) { return c.r == c.g && c.g == c.b; };
  bool grey_media = grey(scene.medium.sigma_s) && grey(scene.medium.sigma_a);
  for (const Volume& v : scene.volumes) grey_media = grey_media && grey(v.sigma_s) && grey(v.sigma_a);
  add(grey_media ? "media:grey" : "media:coloured");
  add(scene.light_model.type == LightModelType::simplified ? "model:simplified" : "model:physical");
  for (const Mesh& mesh : scene.meshes) {
    const bool closed = solid::closed(mesh.positions, mesh.triangles);
    if (is_enclosure(mesh)) {
      add(closed ? "space:room" : "space:ground");
      continue;
    }
    const size_t open = mesh.name.rfind(" (");  // the loader's "objects[i] (label)"
    add("caster:" + (open == std::string::npos ? mesh.name : mesh.name.substr(open + 2, mesh.name.size() - open - 3)));
    if (!closed) add("open_mesh");
    if (!mesh.casts_shadows) add("non_caster");
  }
  if (std::ranges::none_of(scene.meshes, is_enclosure)) add("space:open");
  return out;
}

}  // namespace airlight::harness
