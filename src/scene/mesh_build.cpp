#include "scene/mesh_build.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat4x4.hpp>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <unordered_map>

namespace airlight::scene_mesh {

void TriangleCount::add(const Mesh& mesh, const std::string& file, const std::string& key) {
  triangles_ += mesh.triangles.size();
  if (triangles_ > max_scene_triangles)
    throw InputError(file, key, "the scene's meshes have more than " + std::to_string(max_scene_triangles) +
                                    " triangles in all");
}

bool is_degenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  // In double: float cross products of nearly parallel edges lose all digits.
  const glm::dvec3 ab = glm::dvec3(b) - glm::dvec3(a);
  const glm::dvec3 ac = glm::dvec3(c) - glm::dvec3(a);
  const glm::dvec3 bc = glm::dvec3(c) - glm::dvec3(b);
  const double longest2 = std::max({glm::dot(ab, ab), glm::dot(ac, ac), glm::dot(bc, bc)});
  const double area2 = glm::length(glm::cross(ab, ac));
  return !(area2 > 1e-10 * longest2) || !(longest2 > 0.0);
}

glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  return glm::vec3(glm::normalize(glm::cross(glm::dvec3(b) - glm::dvec3(a),
                                             glm::dvec3(c) - glm::dvec3(a))));
}

uint32_t MeshBuilder::vertex(const glm::vec3& position, const glm::vec3& normal) {
  mesh_.positions.push_back(position);
  mesh_.normals.push_back(glm::normalize(normal));
  return static_cast<uint32_t>(mesh_.positions.size() - 1);
}

void MeshBuilder::triangle(uint32_t a, uint32_t b, uint32_t c) {
  const auto& p = mesh_.positions;
  if (!is_degenerate(p[a], p[b], p[c])) mesh_.triangles.emplace_back(a, b, c);
}

void MeshBuilder::quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  triangle(a, b, c);
  triangle(a, c, d);
}

Mesh MeshBuilder::take(std::string name) {
  mesh_.name = std::move(name);
  return std::move(mesh_);
}

namespace {

using Cell = std::array<int64_t, 3>;

struct CellHash {
  size_t operator()(const Cell& c) const {
    return std::hash<int64_t>()(c[0] * 73856093 ^ c[1] * 19349663 ^ c[2] * 83492791);
  }
};

// Finds the vertex of `welded` within `tolerance` of p through a grid of cells
// the size of the tolerance, so only the 27 cells around p need looking at.
class WeldGrid {
public:
  explicit WeldGrid(float tolerance) : tolerance_(tolerance) {}

  std::optional<uint32_t> find(const glm::vec3& p, const std::vector<glm::vec3>& welded) const {
    const Cell c = cell(p);
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells_.end()) continue;
          for (uint32_t i : it->second)
            if (glm::distance(welded[i], p) <= tolerance_) return i;
        }
    return std::nullopt;
  }
  void insert(const glm::vec3& p, uint32_t index) { cells_[cell(p)].push_back(index); }

private:
  Cell cell(const glm::vec3& p) const {
    return {static_cast<int64_t>(std::floor(p.x / tolerance_)),
            static_cast<int64_t>(std::floor(p.y / tolerance_)),
            static_cast<int64_t>(std::floor(p.z / tolerance_))};
  }
  float tolerance_;
  std::unordered_map<Cell, std::vector<uint32_t>, CellHash> cells_;
};

}  // namespace

void weld(Mesh& mesh, float tolerance) {
  WeldGrid grid(tolerance);
  std::vector<glm::vec3> positions, normal_sums, first_normals;
  std::vector<uint32_t> remap(mesh.positions.size());
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3& p = mesh.positions[i];
    if (const auto found = grid.find(p, positions)) {
      remap[i] = *found;
      normal_sums[*found] += mesh.normals[i];
      continue;
    }
    remap[i] = static_cast<uint32_t>(positions.size());
    grid.insert(p, remap[i]);
    positions.push_back(p);
    normal_sums.push_back(mesh.normals[i]);
    first_normals.push_back(mesh.normals[i]);
  }
  mesh.positions = std::move(positions);
  mesh.normals.resize(normal_sums.size());
  for (size_t i = 0; i < normal_sums.size(); ++i) {
    // Opposite normals can cancel at a fold: keep one of them then.
    const float length = glm::length(normal_sums[i]);
    mesh.normals[i] = length > 1e-3f ? normal_sums[i] / length : first_normals[i];
  }
  std::vector<glm::uvec3> triangles;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::uvec3 w(remap[t.x], remap[t.y], remap[t.z]);
    const auto& p = mesh.positions;
    if (!is_degenerate(p[w.x], p[w.y], p[w.z])) triangles.push_back(w);
  }
  mesh.triangles = std::move(triangles);
}

namespace {

// Boundary edges a → b as a's list of b: a triangle runs a → b and none runs b → a.
std::map<uint32_t, std::vector<uint32_t>> boundary_successors(const Mesh& mesh) {
  std::set<std::pair<uint32_t, uint32_t>> runs;
  for (const glm::uvec3& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) runs.emplace(t[k], t[(k + 1) % 3]);
  std::map<uint32_t, std::vector<uint32_t>> next;
  for (const auto& [a, b] : runs)
    if (!runs.contains({b, a})) next[a].push_back(b);
  return next;
}

// The boundary's loops, each as its vertices in the order the triangles run them. Each step
// takes an unused edge leaving the current vertex, so where loops touch they still close.
std::vector<std::vector<uint32_t>> boundary_loops(const Mesh& mesh) {
  std::map<uint32_t, std::vector<uint32_t>> next = boundary_successors(mesh);
  std::vector<std::vector<uint32_t>> loops;
  for (auto& [start, leaving] : next)
    while (!leaving.empty()) {
      std::vector<uint32_t>& loop = loops.emplace_back();
      for (uint32_t v = start; loop.empty() || v != start;) {
        const auto it = next.find(v);
        if (it == next.end() || it->second.empty())
          throw Failure(mesh.name + ": a boundary edge arrives at a vertex no unused one leaves");
        loop.push_back(v);
        v = it->second.back();
        it->second.pop_back();
      }
    }
  return loops;
}

void cap(MeshBuilder& b, const std::vector<uint32_t>& loop) {
  const uint32_t n = static_cast<uint32_t>(loop.size());
  std::vector<glm::vec3> rim(n);
  glm::dvec3 centre(0.0), normal(0.0);
  for (uint32_t k = 0; k < n; ++k) {
    rim[k] = b.mesh().positions[loop[k]];
    centre += glm::dvec3(rim[k]) / double(n);
  }
  // The fan's triangles (centre, b, a) for each loop edge a → b, their areas summed (Newell).
  for (uint32_t k = 0; k < n; ++k)
    normal += glm::cross(glm::dvec3(rim[(k + 1) % n]) - centre, glm::dvec3(rim[k]) - centre);
  const glm::vec3 flat(glm::normalize(normal));
  const uint32_t apex = b.vertex(glm::vec3(centre), flat);
  const uint32_t first = static_cast<uint32_t>(b.mesh().positions.size());
  for (const glm::vec3& q : rim) b.vertex(q, flat);
  for (uint32_t k = 0; k < n; ++k) b.triangle(apex, first + (k + 1) % n, first + k);
}

}  // namespace

void cap_holes(Mesh& mesh) {
  const std::vector<std::vector<uint32_t>> loops = boundary_loops(mesh);
  std::string name = mesh.name;
  MeshBuilder b(std::move(mesh));
  for (const std::vector<uint32_t>& loop : loops) cap(b, loop);
  mesh = b.take(std::move(name));
}

glm::mat3 Transform::rotation() const {
  const glm::vec3 r = glm::radians(rotate_deg);
  const glm::mat4 m = glm::rotate(glm::mat4(1.0f), r.z, glm::vec3(0, 0, 1)) *
                      glm::rotate(glm::mat4(1.0f), r.y, glm::vec3(0, 1, 0)) *
                      glm::rotate(glm::mat4(1.0f), r.x, glm::vec3(1, 0, 0));
  return glm::mat3(m);
}

void apply(const Transform& transform, Mesh& mesh) {
  const glm::mat3 r = transform.rotation();
  for (glm::vec3& p : mesh.positions) p = r * (transform.scale * p) + transform.translate;
  // A uniform scale leaves normals' directions alone; renormalize for rounding.
  for (glm::vec3& n : mesh.normals) n = glm::normalize(r * n);
  for (std::optional<OrientedBox>* box : {&mesh.outer_box, &mesh.inner_box}) {
    if (!*box) continue;
    (*box)->center = r * (transform.scale * (*box)->center) + transform.translate;
    (*box)->axes = r * (*box)->axes;
    (*box)->half *= transform.scale;
  }
}

}  // namespace airlight::scene_mesh
