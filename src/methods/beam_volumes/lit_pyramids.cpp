#include "methods/beam_volumes/lit_pyramids.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <unordered_map>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace airlight::methods {
namespace {

// How far the influence volume's backplate lies from the light: past every
// point a view ray of this frame can reach before the far plane.
double backplate_distance(const FrameInputs& inputs, const Light& light) {
  const double eye_to_light = glm::length(glm::dvec3(light.position) - glm::dvec3(inputs.camera.position));
  return 2.0 * (eye_to_light + inputs.camera.far) + 1.0;
}

// Whether x lies inside the pyramid from the light to `base` (the prism toward
// a directional light): on the light's side of the base's plane and inside
// every side's. The beam tree cannot say it for the eye: outside the influence
// volume its beams meet no polygon and it answers lit.
bool inside_pyramid(const geometry::BeamPolygon& base, const Light& light, const glm::dvec3& x) {
  const bool directional = light.type == LightType::directional;
  const glm::dvec3 l(light.position), d(light.direction);
  const std::vector<glm::dvec3>& v = base.vertices;
  glm::dvec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
  const double winding = glm::dot(normal, directional ? d : v[0] - l) < 0.0 ? -1.0 : 1.0;  // away from the light
  if (winding * glm::dot(normal, x - v[0]) >= 0.0) return false;
  for (size_t k = 0; k < v.size(); ++k) {
    const glm::dvec3 a = v[k], b = v[(k + 1) % v.size()];
    const glm::dvec3 side = directional ? glm::cross(b - a, -d) : glm::cross(b - a, l - a);
    if (winding * glm::dot(side, x - a) < 0.0) return false;
  }
  return true;
}

}  // namespace

// The visible set made conforming: vertices within `tolerance` welded, and
// every edge split at the vertices that lie on it (T-junctions, where the
// beam tree cut one piece and not its neighbour), so that two pieces share an
// edge vertex for vertex. Their pyramids' sides along it are then the same
// triangles with opposite windings, which cancel exactly; otherwise the
// rasterizer covers a side and the two that replace it along the neighbour
// differently, leaving unmatched crossings that flip a light's count along
// the rest of the ray.
class ConformingSet {
public:
  ConformingSet(const std::vector<geometry::BeamPolygon>& pieces, double tolerance) : tolerance_(tolerance) {
    glm::dvec3 lo(INFINITY), hi(-INFINITY);
    for (const auto& p : pieces)
      for (const glm::dvec3& v : p.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    origin_ = lo;
    size_t count = 0;
    for (const auto& p : pieces) count += p.vertices.size();
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, tolerance});
    cell_ = std::max(extent / std::cbrt(std::max<double>(count, 1.0)), 4.0 * tolerance);
    for (const auto& p : pieces) {
      std::vector<int> loop;
      for (const glm::dvec3& v : p.vertices) loop.push_back(weld(v));
      loops_.push_back(std::move(loop));
    }
  }

  // Piece k's loop of welded vertices with every vertex that lies on one of its edges inserted.
  std::vector<int> conforming(size_t k) const {
    std::vector<int> out;
    const std::vector<int>& loop = loops_[k];
    for (size_t e = 0; e < loop.size(); ++e) {
      const int a = loop[e], b = loop[(e + 1) % loop.size()];
      if (a == b) continue;
      out.push_back(a);
      for (int m : on_edge(a, b)) out.push_back(m);
    }
    return out;
  }
  const glm::dvec3& vertex(int id) const { return vertices_[id]; }
  // Whether b lies within `tolerance` of the line through a and c.
  bool collinear(int a, int b, int c) const {
    const glm::dvec3 d = vertices_[c] - vertices_[a];
    const double length = glm::length(d);
    return length > 0.0 && glm::length(glm::cross(vertices_[b] - vertices_[a], d)) / length <= tolerance_;
  }
  size_t size() const { return loops_.size(); }

private:
  using Key = std::array<long long, 3>;
  struct KeyHash {
    size_t operator()(const Key& k) const { return std::hash<long long>()(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL); }
  };
  Key key(const glm::dvec3& x) const {
    const glm::dvec3 c = glm::floor((x - origin_) / cell_);
    return {static_cast<long long>(c.x), static_cast<long long>(c.y), static_cast<long long>(c.z)};
  }

  int weld(const glm::dvec3& v) {
    const Key k = key(v);
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto it = grid_.find({k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == grid_.end()) continue;
          for (int id : it->second)
            if (glm::distance(vertices_[id], v) <= tolerance_) return id;
        }
    vertices_.push_back(v);
    grid_[k].push_back(static_cast<int>(vertices_.size()) - 1);
    return static_cast<int>(vertices_.size()) - 1;
  }

  // The welded vertices strictly inside segment a → b within `tolerance` of it, from a to b.
  std::vector<int> on_edge(int a, int b) const {
    const glm::dvec3 p = vertices_[a], q = vertices_[b], d = q - p;
    const double length2 = glm::dot(d, d);
    std::vector<std::pair<double, int>> found;
    const Key lo = key(glm::min(p, q) - tolerance_), hi = key(glm::max(p, q) + tolerance_);
    for (long long x = lo[0]; x <= hi[0]; ++x)
      for (long long y = lo[1]; y <= hi[1]; ++y)
        for (long long z = lo[2]; z <= hi[2]; ++z) {
          const auto it = grid_.find({x, y, z});
          if (it == grid_.end()) continue;
          for (int id : it->second) {
            if (id == a || id == b) continue;
            const double s = glm::dot(vertices_[id] - p, d) / length2;
            if (s <= 0.0 || s >= 1.0) continue;
            if (glm::distance(p + s * d, vertices_[id]) <= tolerance_) found.emplace_back(s, id);
          }
        }
    std::sort(found.begin(), found.end());
    std::vector<int> ids;
    for (const auto& f : found) ids.push_back(f.second);
    return ids;
  }

  double tolerance_, cell_ = 1.0;
  glm::dvec3 origin_{0.0};
  std::vector<glm::dvec3> vertices_;
  std::vector<std::vector<int>> loops_;
  std::unordered_map<Key, std::vector<int>, KeyHash> grid_;
};


void LitPyramids::prepare(const Scene& scene) {
  casters_.clear();
  caster_meshes_.clear();
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (scene.meshes[m].casts_shadows) {
      casters_.push_back(&scene.meshes[m]);
      caster_meshes_.push_back(static_cast<int>(m));
    }
}

std::vector<geometry::BeamPolygon> LitPyramids::world_polygons(const FrameInputs& inputs) const {
  std::vector<geometry::BeamPolygon> polygons;
  for (size_t c = 0; c < casters_.size(); ++c) {
    const Mesh& mesh = *casters_[c];
    const glm::dmat4 m = inputs.transforms.empty() ? glm::dmat4(1.0) : glm::dmat4(inputs.transforms[caster_meshes_[c]]);
    for (const glm::uvec3& t : mesh.triangles) {
      geometry::BeamPolygon p;
      p.source = caster_meshes_[c];
      for (int k = 0; k < 3; ++k) p.vertices.push_back(glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[t[k]]), 1.0)));
      polygons.push_back(std::move(p));
    }
  }
  return polygons;
}

// A face of a pyramid, its plane oriented out of the pyramid (a, b, c counter-
// clockwise seen from outside): crossing it inward lowers the light's count
// by 1, so that inside a pyramid the count is 0 (lit).
void LitPyramids::add_face(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, int index) {
  triangles_.push_back({{glm::vec4(a), glm::vec4(b), glm::vec4(c)}, kit::counted_plane(a, b, c), glm::ivec4(index, 1, 0, 0)});
}

// The pyramids from the light to the conforming visible set (Nilsson §3.2),
// or the prisms from it back toward a directional light, to infinity (w = 0):
// each base, and a side per edge that no neighbour shares (a shared side
// appears once in each direction and cancels), each wound to face out of its
// pyramid.
void LitPyramids::add_pyramids(const ConformingSet& set, const Light& light, int index) {
  const bool directional = light.type == LightType::directional;
  const glm::dvec4 apex = directional ? glm::dvec4(-glm::dvec3(light.direction), 0.0) : glm::dvec4(glm::dvec3(light.position), 1.0);
  std::vector<std::vector<int>> loops;
  std::map<std::pair<int, int>, int> edges;  // directed, of the bases wound away from the light: how many
  for (size_t k = 0; k < set.size(); ++k) {
    std::vector<int> loop = set.conforming(k);
    if (loop.size() < 3) continue;
    const glm::dvec3 v0 = set.vertex(loop[0]);
    glm::dvec3 normal(0.0);  // Newell's: robust with the collinear vertices the splits insert
    for (size_t e = 0; e < loop.size(); ++e) normal += glm::cross(set.vertex(loop[e]) - v0, set.vertex(loop[(e + 1) % loop.size()]) - v0);
    const glm::dvec3 away = directional ? glm::dvec3(light.direction) : v0 - glm::dvec3(light.position);
    if (glm::dot(normal, away) < 0.0) std::reverse(loop.begin(), loop.end());
    for (size_t e = 0; e < loop.size(); ++e) ++edges[{loop[e], loop[(e + 1) % loop.size()]}];
    loops.push_back(std::move(loop));
  }
  const auto at = [&](int id) { return glm::dvec4(set.vertex(id), 1.0); };
  for (const std::vector<int>& loop : loops) {
    // The base as a fan over its corners alone: the vertices the splits
    // inserted are collinear, and their slivers' planes would be noise.
    std::vector<int> corners;
    for (size_t e = 0; e < loop.size(); ++e)
      if (!set.collinear(loop[(e + loop.size() - 1) % loop.size()], loop[e], loop[(e + 1) % loop.size()]))
        corners.push_back(loop[e]);
    for (size_t k = 1; k + 1 < corners.size(); ++k) add_face(at(corners[0]), at(corners[k]), at(corners[k + 1]), index);
    for (size_t e = 0; e < loop.size(); ++e) {
      const int a = loop[e], b = loop[(e + 1) % loop.size()];
      // Cancelled only where exactly two pyramids share the side: pieces that
      // overlap by ε as seen from the light can meet an edge more often.
      const auto reverse = edges.find({b, a});
      if (reverse == edges.end() || reverse->second != 1 || edges[{a, b}] != 1) add_face(at(b), at(a), apex, index);
    }
  }
}

void LitPyramids::build(const FrameInputs& inputs) {
  const auto start = std::chrono::steady_clock::now();
  triangles_.clear();
  eye_counts_.assign(inputs.lights.size(), 1);
  nodes_ = visible_ = 0;
  const std::vector<geometry::BeamPolygon> polygons = world_polygons(inputs);
  for (size_t i = 0; i < inputs.lights.size(); ++i) {
    const Light& light = inputs.lights[i];
    std::vector<geometry::BeamPolygon> scene = polygons;
    const auto backplate = geometry::influence_backplate(light, backplate_distance(inputs, light));
    scene.insert(scene.end(), backplate.begin(), backplate.end());
    const geometry::LightOrigin origin = geometry::light_origin(light);
    const double epsilon = geometry::beam_epsilon(origin, polygons);
    const geometry::BeamTree tree(origin, scene, epsilon);
    nodes_ += tree.node_count();
    visible_ += static_cast<int>(tree.visible_set().size());
    const glm::dvec3 eye(inputs.camera.position);
    for (const geometry::BeamPolygon& p : tree.visible_set())
      if (inside_pyramid(p, light, eye)) eye_counts_[i] = 0;
    add_pyramids(ConformingSet(tree.visible_set(), epsilon), light, static_cast<int>(i));
  }
  build_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::vector<std::pair<std::string, double>> LitPyramids::stats() const {
  return {{"beam_tree_nodes", static_cast<double>(nodes_)},
          {"visible_polygons", static_cast<double>(visible_)},
          {"pyramid_faces", static_cast<double>(triangles_.size())},
          {"build_s", build_s_}};
}

}  // namespace airlight::methods
