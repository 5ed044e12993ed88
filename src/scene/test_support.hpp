#pragma once
// Shared checks for the scene layer's tests.
#include "core/test_paths.hpp"
#include "scene/mesh_build.hpp"

#include <airlight/error.hpp>
#include <airlight/scene.hpp>
#include <array>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <gtest/gtest.h>
#include <map>
#include <string>
#include <utility>

namespace airlight::scene_test {

inline std::filesystem::path data_dir() {
  return test::test_data() / "scenes";
}

// Runs f and checks that it throws InputError naming `file` and `key`, its message
// exactly `message` (any message when empty).
template <class F>
::testing::AssertionResult throws_input_error(F f, const std::string& file, const std::string& key,
                                              const std::string& message = "") {
  try {
    f();
  } catch (const InputError& e) {
    const bool said = message.empty() || e.message() == message;
    if (e.file() == file && e.key() == key && said) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "file \"" << e.file() << "\", key \"" << e.key()
                                         << "\" (" << e.what() << "); expected file \"" << file
                                         << "\", key \"" << key << "\", message \"" << message
                                         << "\"";
  }
  return ::testing::AssertionFailure() << "no InputError thrown";
}

inline bool finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// What every mesh must satisfy: sizes agree, indices in range, finite
// positions, unit normals, no degenerate triangles.
inline ::testing::AssertionResult well_formed(const Mesh& mesh) {
  if (mesh.normals.size() != mesh.positions.size())
    return ::testing::AssertionFailure() << mesh.name << ": normals and positions differ in size";
  if (mesh.triangles.empty()) return ::testing::AssertionFailure() << mesh.name << ": no triangles";
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!finite(mesh.positions[i]) || !finite(mesh.normals[i]))
      return ::testing::AssertionFailure() << mesh.name << ": vertex " << i << " not finite";
    if (std::fabs(glm::length(mesh.normals[i]) - 1.0f) > 1e-5f)
      return ::testing::AssertionFailure() << mesh.name << ": normal " << i << " not unit";
  }
  for (const glm::uvec3& t : mesh.triangles) {
    if (t.x >= mesh.positions.size() || t.y >= mesh.positions.size() ||
        t.z >= mesh.positions.size())
      return ::testing::AssertionFailure() << mesh.name << ": index out of range";
    if (scene_mesh::is_degenerate(mesh.positions[t.x], mesh.positions[t.y], mesh.positions[t.z]))
      return ::testing::AssertionFailure() << mesh.name << ": degenerate triangle";
  }
  if (!finite(mesh.albedo) || glm::any(glm::lessThan(mesh.albedo, glm::vec3(0.0f))) ||
      glm::any(glm::greaterThan(mesh.albedo, glm::vec3(1.0f))))
    return ::testing::AssertionFailure() << mesh.name << ": albedo outside [0, 1]";
  return ::testing::AssertionSuccess();
}

// The fraction of triangles whose winding disagrees with their vertex normals
// (the face normal points away from the vertex normals' mean).
inline double misoriented_fraction(const Mesh& mesh) {
  size_t bad = 0;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 n = scene_mesh::face_normal(mesh.positions[t.x], mesh.positions[t.y],
                                                mesh.positions[t.z]);
    const glm::vec3 mean = mesh.normals[t.x] + mesh.normals[t.y] + mesh.normals[t.z];
    if (glm::dot(n, mean) <= 0.0f) ++bad;
  }
  return double(bad) / double(mesh.triangles.size());
}

// Whether the mesh, welded by exact position, is closed: every edge run by exactly two
// triangles, once in each direction (what counting shadow volumes needs, Biri §5.1.1).
inline ::testing::AssertionResult closed_after_welding(const Mesh& mesh) {
  std::map<std::array<float, 3>, uint32_t> index_of;  // +0.0f: −0 and +0 are one position
  const auto welded = [&](uint32_t i) {
    const glm::vec3& p = mesh.positions[i];
    return index_of.try_emplace({p.x + 0.0f, p.y + 0.0f, p.z + 0.0f}, uint32_t(index_of.size())).first->second;
  };
  std::map<std::pair<uint32_t, uint32_t>, int> runs;
  for (const glm::uvec3& t : mesh.triangles) {
    const uint32_t w[3] = {welded(t.x), welded(t.y), welded(t.z)};
    for (int k = 0; k < 3; ++k) ++runs[{w[k], w[(k + 1) % 3]}];
  }
  size_t unmatched = 0;
  for (const auto& [edge, count] : runs) {
    const auto back = runs.find({edge.second, edge.first});
    unmatched += count != 1 || back == runs.end() || back->second != 1;
  }
  if (unmatched == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << mesh.name << ": " << unmatched << " of " << runs.size()
                                       << " directed edges not matched once by their reverse";
}

// The signed volume enclosed by a closed mesh (positive when it winds outward).
inline double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
    volume += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  return volume;
}

}  // namespace airlight::scene_test
