#include "core/solid.hpp"
#include "core/warning.hpp"
#include "scene/json_reader.hpp"
#include "scene/mesh_build.hpp"
#include "scene/shapes.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <array>
#include <cfloat>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <map>
#include <sstream>
#include <string>
#include <vector>
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

  // tinyobjloader reads a coordinate beyond float range ("1e999") as infinite.
  void check_positions() const {
    for (int i = 0; i < position_count_; ++i) {
      const glm::dvec3 p = position(i);
      const std::string key = "vertex " + std::to_string(i + 1);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail(key, "has a coordinate beyond float range (larger than " + scene_json::number_text(FLT_MAX) + ")");
      if (glm::length(p) > 1e30) fail(key, "is too far from the origin (more than 1e+30)");
    }
  }

  // A polygon, fanned into triangles from its first corner.
  void face(const std::vector<Corner>& corners, size_t face_number) {
    const std::string key = "face " + std::to_string(face_number);
    if (corners.size() < 3) fail(key, "has fewer than 3 vertices");
    for (const Corner& c : corners) check_corner(c, key);
    for (size_t k = 1; k + 1 < corners.size(); ++k) {
      const Corner tri[3] = {corners[0], corners[k], corners[k + 1]};
      const std::array<glm::vec3, 3> p = {glm::vec3(position(tri[0].first)), glm::vec3(position(tri[1].first)),
                                          glm::vec3(position(tri[2].first))};
      if (is_degenerate(p[0], p[1], p[2])) {
        skipped_.push_back({face_number, p});
        continue;
      }
      mesh_.triangles.emplace_back(index(tri[0]), index(tri[1]), index(tri[2]));
      add_to_smooth_normals(tri);
    }
  }

  Mesh finish(std::string name) {
    if (mesh_.triangles.empty()) fail("", "has no faces");
    check_skipping_keeps_closed();
    if (!skipped_.empty()) {
      const size_t n = skipped_.size();
      warn(file_, "skipped " + std::to_string(n) + " degenerate triangle" + (n == 1 ? "" : "s") + " (zero area)");
    }
    mesh_.normals.resize(mesh_.positions.size());
    for (const auto& [corner, i] : indices_) mesh_.normals[i] = vertex_normal(corner);
    mesh_.name = std::move(name);
    return std::move(mesh_);
  }

private:
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError(file_, key, message);
  }

  // A zero-area triangle with a repeated corner joins nothing once welded by position, but
  // one with three distinct corners in a line can close a surface: the faces beside a
  // T-junction meet its three edges. Skipping that one would open the surface, so the file
  // is refused instead, saying how to mend it.
  void check_skipping_keeps_closed() const {
    if (skipped_.empty() || solid::closed(mesh_.positions, mesh_.triangles)) return;
    std::vector<glm::vec3> positions = mesh_.positions;
    std::vector<glm::uvec3> triangles = mesh_.triangles;
    for (const Skipped& s : skipped_) {
      const auto first = static_cast<uint32_t>(positions.size());
      positions.insert(positions.end(), s.corners.begin(), s.corners.end());
      triangles.emplace_back(first, first + 1, first + 2);
    }
    if (!solid::closed(positions, triangles)) return;
    for (const Skipped& s : skipped_) {
      const auto& c = s.corners;
      if (c[0] != c[1] && c[1] != c[2] && c[2] != c[0])
        fail("face " + std::to_string(s.face),
             "has zero area (its corners lie on a line) but closes the surface, which skipping it would "
             "open; split the face across its longest edge at its middle corner instead");
    }
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

  struct Skipped {
    size_t face;
    std::array<glm::vec3, 3> corners;
  };

  const tinyobj::attrib_t& attrib_;
  std::string file_;
  int position_count_, normal_count_;
  Mesh mesh_;
  std::map<Corner, uint32_t> indices_;
  std::map<int, SmoothNormal> smooth_;
  std::vector<Skipped> skipped_;  // zero-area triangles, left out with a warning
};

// tinyobjloader reads "nan", "inf" and words that are not numbers as 0 and a
// missing coordinate as 0: the text says what was written.
void check_vertex_text(const std::string& text, const std::string& file) {
  std::istringstream lines(text);
  int vertex = 0;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string tag;
    if (!(words >> tag) || tag != "v") continue;
    const std::string key = "vertex " + std::to_string(++vertex);
    int count = 0;
    for (std::string word; count < 3 && words >> word; ++count) {
      double x = 0.0;
      const char* end = word.data() + word.size();
      const auto [stop, ec] = std::from_chars(word.data() + (word[0] == '+'), end, x);
      if (ec == std::errc::invalid_argument || stop != end)
        throw InputError(file, key, "has a coordinate that is not a number ('" + word + "')");
      if (ec == std::errc() && !std::isfinite(x))
        throw InputError(file, key, "has a non-finite coordinate (" + word + ")");
    }
    if (count < 3) throw InputError(file, key, "has fewer than 3 coordinates");
  }
}

std::string counted(size_t n, const std::string& what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); }

// Lines (l) and points (p) have no area to cast a shadow or end a view ray: left
// out, with one warning that counts them.
void warn_lines_and_points(const std::vector<tinyobj::shape_t>& shapes, const std::string& file) {
  size_t lines = 0, points = 0;
  for (const tinyobj::shape_t& shape : shapes) {
    lines += shape.lines.num_line_vertices.size();
    points += shape.points.indices.size();
  }
  if (lines + points > 0)
    warn(file, "skipped " + counted(lines, "line") + " and " + counted(points, "point") + " (airlight renders faces)");
}

// Materials play no part (an object's albedo comes from the scene file), so a
// usemtl whose .mtl file is missing is no error; the warning says it is ignored.
void warn_missing_materials(const std::string& text, const std::filesystem::path& file, const FileSource& files) {
  std::istringstream lines(text);
  std::vector<std::string> libraries;
  bool uses = false, found = false;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    uses = uses || tag == "usemtl";
    if (tag != "mtllib") continue;
    for (std::string name; words >> name;) {
      libraries.push_back(name);
      found = found || files.exists(file.parent_path() / name);
    }
  }
  if (uses && !found)
    warn(file.string(), "usemtl without its material file (" +
                            (libraries.empty() ? std::string("no mtllib line") : libraries.front() + " is not there") +
                            "): materials are ignored, the object's albedo applies");
}

}  // namespace

Mesh load_obj(const std::filesystem::path& file, const FileSource& files) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // faces keep the numbers the file gives them
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From a string with no material text: materials play no part here.
  const std::string text = files.read(file);
  check_vertex_text(text, file.string());
  if (!reader.ParseFromString(text, "", config)) {
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
  Mesh mesh = builder.finish(file.filename().string());
  warn_lines_and_points(reader.GetShapes(), file.string());
  warn_missing_materials(text, file, files);
  return mesh;
}

}  // namespace airlight::scene_mesh
