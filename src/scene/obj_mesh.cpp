#include "scene/mesh_build.hpp"
#include "scene/shapes.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <map>
#include <sstream>
#include <tiny_obj_loader.h>

namespace airlight::scene_mesh {
namespace {

// One OBJ corner: a position index and an optional normal index (-1 = none).
using Corner = std::pair<int, int>;

class ObjBuilder {
public:
  ObjBuilder(const tinyobj::attrib_t& attrib, std::string file)
      : attrib_(attrib), file_(std::move(file)),
        position_count_(static_cast<int>(attrib.vertices.size() / 3)),
        normal_count_(static_cast<int>(attrib.normals.size() / 3)) {}

  void check_positions() const {
    for (int i = 0; i < position_count_; ++i) {
      const glm::dvec3 p = position(i);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
          glm::length(glm::abs(p)) > 1e30) {
        fail("vertex " + std::to_string(i + 1), "has a non-finite coordinate");
      }
    }
  }

  // A polygon, fanned into triangles from its first corner.
  void face(const std::vector<Corner>& corners, size_t face_number) {
    const std::string key = "face " + std::to_string(face_number);
    if (corners.size() < 3) fail(key, "has fewer than 3 vertices");
    for (const Corner& c : corners) check_corner(c, key);
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      const Corner tri[3] = {corners[0], corners[k], corners[k + 1]};
      if (is_degenerate(glm::vec3(position(tri[0].first)), glm::vec3(position(tri[1].first)),
                        glm::vec3(position(tri[2].first)))) {
        fail(key, "has zero area (a degenerate triangle)");
      }
      mesh_.triangles.emplace_back(index(tri[0]), index(tri[1]), index(tri[2]));
      add_to_smooth_normals(tri);
    }
  }

  Mesh finish(std::string name) {
    if (mesh_.triangles.empty()) fail("", "has no faces");
    mesh_.normals.resize(mesh_.positions.size());
    for (const auto& [corner, i] : indices_) mesh_.normals[i] = vertex_normal(corner);
    mesh_.name = std::move(name);
    return std::move(mesh_);
  }

private:
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError(file_, key, message);
  }

  glm::dvec3 position(int i) const {
    const auto& v = attrib_.vertices;
    return {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
  }

  void check_corner(const Corner& c, const std::string& key) const {
    if (c.first < 0 || c.first >= position_count_) fail(key, "refers to a missing vertex");
    if (c.second < -1 || c.second >= normal_count_) fail(key, "refers to a missing normal");
  }

  uint32_t index(const Corner& c) {
    const auto [it, added] = indices_.try_emplace(c, static_cast<uint32_t>(mesh_.positions.size()));
    if (added) mesh_.positions.push_back(glm::vec3(position(c.first)));
    return it->second;
  }

  // Face normals weighted by the corner's angle, summed per position: the
  // normal a corner gets when the file gives it none. Angle weights do not
  // depend on how polygons were split into triangles.
  void add_to_smooth_normals(const Corner (&tri)[3]) {
    const glm::dvec3 p[3] = {position(tri[0].first), position(tri[1].first),
                             position(tri[2].first)};
    const glm::dvec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 a = glm::normalize(p[(k + 1) % 3] - p[k]);
      const glm::dvec3 b = glm::normalize(p[(k + 2) % 3] - p[k]);
      const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
      smooth_.try_emplace(tri[k].first, SmoothNormal{{}, n}).first->second.sum += angle * n;
    }
  }

  glm::vec3 vertex_normal(const Corner& c) const {
    if (c.second >= 0) {
      const auto& n = attrib_.normals;
      const glm::dvec3 given(n[3 * c.second], n[3 * c.second + 1], n[3 * c.second + 2]);
      const double length = glm::length(given);
      if (std::isfinite(length) && length > 1e-12) return glm::vec3(given / length);
    }
    const SmoothNormal& s = smooth_.at(c.first);
    const double length = glm::length(s.sum);
    // Faces back to back can cancel: fall back to the first face's normal.
    return glm::vec3(length > 1e-9 ? s.sum / length : s.first);
  }

  struct SmoothNormal {
    glm::dvec3 sum, first;  // first: the unit normal of the first face
  };

  const tinyobj::attrib_t& attrib_;
  std::string file_;
  int position_count_, normal_count_;
  Mesh mesh_;
  std::map<Corner, uint32_t> indices_;
  std::map<int, SmoothNormal> smooth_;
};

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file.string(), "", "cannot read the file");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

Mesh load_obj(const std::filesystem::path& file) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // faces keep the numbers the file gives them
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From a string with no material text: materials play no part here.
  if (!reader.ParseFromString(read_text(file), "", config)) {
    throw InputError(file.string(), "", "malformed OBJ: " + reader.Error());
  }
  ObjBuilder builder(reader.GetAttrib(), file.string());
  builder.check_positions();
  size_t face_number = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    size_t offset = 0;
    for (const unsigned char count : shape.mesh.num_face_vertices) {
      std::vector<Corner> corners;
      for (size_t k = 0; k < count; ++k) {
        const tinyobj::index_t& i = shape.mesh.indices[offset + k];
        corners.emplace_back(i.vertex_index, i.normal_index);
      }
      offset += count;
      builder.face(corners, ++face_number);
    }
  }
  return builder.finish(file.filename().string());
}

}  // namespace airlight::scene_mesh
