#pragma once
// What the built-in scenes (builtin_families.hpp) share in building them:
// meshes placed as objects, spot lights, one-lobe phase functions, the floor
// slab, and a directional light's beam through an opening.
#include "scene/mesh_build.hpp"
#include "scene/shapes.hpp"

#include <airlight/scene.hpp>
#include <string>
#include <vector>

namespace airlight::scene_builtin {

// `mesh` moved by `transform` (none: where it is), in `albedo`, named `name`.
Mesh place(Mesh mesh, const scene_mesh::Transform& transform, Color albedo, const std::string& name);
Mesh place(Mesh mesh, Color albedo, const std::string& name);

// A box from `min` to `max` added to `s`.
void add_box(Scene& s, const glm::vec3& min, const glm::vec3& max, Color albedo, const std::string& name);

// Each of `pieces` (a room, a table, a column: shapes.hpp) added to `s` where it
// is, in `albedo`, under its piece's name.
void add_pieces(Scene& s, std::vector<Mesh> pieces, Color albedo);

Light spot(glm::vec3 position, glm::vec3 target, Color intensity, float cone_deg, float edge_deg = 0.0f);

Phase single_lobe(PhaseType type, float g = 0.0f);

// A thick floor slab: a closed box is friendlier to silhouette methods than a plane.
Mesh floor_slab(float half_size, Color albedo);

// The beam of the directional light `sun` through `opening` (scene.hpp: Beam).
// Its rectangle lies upstream of the whole opening, `margin` clear of it;
// across the light it covers the opening's projection along the light with
// `margin` to spare; it reaches past every corner of `room`. The rectangle's
// axes are the gobo frame of docs/design.md §1 (optics::gobo_frame, out of this layer's
// reach): right = normalize(direction × gobo_up), up = right × direction.
Beam beam_through(const Light& sun, const scene_mesh::Extent& opening, const scene_mesh::Extent& room, float margin);

}  // namespace airlight::scene_builtin
