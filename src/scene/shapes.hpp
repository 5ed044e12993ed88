#pragma once
// The meshes objects are made of (docs/design.md §4 "objects"). All are in object
// space; the caller applies the object's Transform. Conventions as in
// mesh_build.hpp: counter-clockwise outward winding, unit normals, no
// degenerate triangles.
#include "core/file_source.hpp"

#include <airlight/scene.hpp>
#include <filesystem>
#include <glm/vec2.hpp>
#include <optional>
#include <vector>

namespace airlight::scene_mesh {

// Axis-aligned box; flat faces, so each face has its own 4 vertices.
Mesh make_box(const glm::vec3& min, const glm::vec3& max);

// UV sphere: `segments` around the y axis, segments/2 rings, one vertex per pole.
Mesh make_sphere(const glm::vec3& center, float radius, int segments);

// A one-sided rectangle: `size` (x, z extent) in the plane through `center`
// with unit `normal`; its edges follow world x and z turned by the shortest
// rotation taking +y to `normal` (a half turn about x for -y).
Mesh make_plane(const glm::vec3& center, glm::vec2 size, const glm::vec3& normal);

// Capped cylinder along +y from the centre of its base: smooth side, flat caps.
Mesh make_cylinder(const glm::vec3& base, float radius, float height, int segments);

// A semicircular arch: the half annulus between the radii above `center` in the
// xy plane, `depth` thick along z about it, in `segments` voussoirs; its two
// ends stand on the plane y = center.y. Smooth curved faces, flat sides and ends.
Mesh make_arch(const glm::vec3& center, float inner_radius, float outer_radius, float depth,
               int segments);

// The Utah teapot (Newell's 32 bicubic patches), `segments`×`segments` quads
// per patch, y up, spout toward +x, standing on y = 0 and 1 unit tall.
Mesh make_teapot(int segments);

// An axis-aligned region of space: a room's inside, a window opening.
struct Extent {
  glm::vec3 min, max;
};

// The shapes of several pieces below (the built-in scenes' furniture) give each
// piece the name of its part: "left wall", "table leg".

// A closed room around `inside`, of slabs `wall` thick, with `window` (an
// opening through the wall at z = inside.min.z), if any, left open: that wall
// is then built from the four boxes around the opening.
std::vector<Mesh> make_room(const Extent& inside, const std::optional<Extent>& window, float wall);

// A table standing on y = 0: a top 5 cm thick on four legs.
std::vector<Mesh> make_table(const glm::vec3& centre_of_top, glm::vec2 size);

// A column standing on y = 0 at (x, z) = `at`, `height` tall: a square plinth,
// a round shaft of `segments`, a square capital.
std::vector<Mesh> make_column(glm::vec2 at, float height, int segments);

// A Wavefront OBJ file; polygons are fanned into triangles. Throws InputError
// naming the OBJ file, with keys "face N" / "vertex N" (1-based, file order). Its
// material files are looked for in `files`.
Mesh load_obj(const std::filesystem::path& file, const FileSource& files = disk_files());

}  // namespace airlight::scene_mesh
