#pragma once
// Building blocks for the meshes the scene layer makes: an indexed builder that
// refuses degenerate triangles, vertex welding, and object transforms.
//
// Conventions for every mesh made here: triangles wind counter-clockwise seen
// from the side their normals point to (outward for closed shapes), and every
// normal is unit length.
#include <airlight/scene.hpp>
#include <glm/mat3x3.hpp>

namespace airlight::scene_mesh {

// The most triangles a scene's meshes may have in all. A few bytes of a scene make
// many (a sphere's segments, an object or a glTF node naming a mesh again), and
// building them is the loader's longest work: counted as each mesh is added.
inline constexpr size_t max_scene_triangles = size_t(1) << 21;

// The triangles of a scene's meshes so far.
class TriangleCount {
public:
  // Throws InputError(file, key) once the meshes added have more than max_scene_triangles.
  void add(const Mesh& mesh, const std::string& file, const std::string& key);

private:
  size_t triangles_ = 0;
};

// True when the triangle has (numerically) zero area: its doubled area is below
// 1e-10 of its longest edge squared, so a normal computed from it is unreliable.
bool is_degenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// The unit normal of a triangle by the counter-clockwise rule (caller ensures
// the triangle is not degenerate).
glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

class MeshBuilder {
public:
  MeshBuilder() = default;
  explicit MeshBuilder(Mesh mesh) : mesh_(std::move(mesh)) {}  // to add to a mesh
  uint32_t vertex(const glm::vec3& position, const glm::vec3& normal);
  // Adds the triangle unless it is degenerate (pole collapses in tessellations).
  void triangle(uint32_t a, uint32_t b, uint32_t c);
  // The quad a b c d (counter-clockwise) as two triangles.
  void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d);
  Mesh take(std::string name);
  const Mesh& mesh() const { return mesh_; }

private:
  Mesh mesh_;
};

// Merges vertices closer than `tolerance`, averaging their normals, and drops
// the triangles that collapse. Used to stitch patches into one surface.
void weld(Mesh& mesh, float tolerance);

// Closes each boundary loop of a welded mesh (one index per position) with a fan from the
// loop's centroid, run against the loop so that the winding stays consistent (outward for a
// surface wound outward), with the cap's flat normal. The cap's own vertices repeat the
// loop's positions, so the result is closed once welded by position. Meant for holes whose
// rim is star-shaped about its centroid (no fan triangle degenerate), as the teapot's are.
// A boundary edge is one that a triangle runs and none runs back. Throws airlight::Failure if the boundary edges do
// not form loops (a vertex where more of them arrive than leave).
void cap_holes(Mesh& mesh);

// Object placement: scale, then rotate about X, then Y, then Z (world axes,
// right-handed, degrees), then translate.
struct Transform {
  glm::vec3 translate{0.0f};
  glm::vec3 rotate_deg{0.0f};
  float scale = 1.0f;
  glm::mat3 rotation() const;
};
void apply(const Transform& transform, Mesh& mesh);

}  // namespace airlight::scene_mesh
