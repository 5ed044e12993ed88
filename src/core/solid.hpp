#pragma once
// Closed triangle meshes as solids, for Nilsson's inner bounding volumes (§5.1), which must
// lie inside their object: the scene loader checks the ones a file gives and the geometry
// layer computes the others, so both use these plain-glm tests.
#include <airlight/box.hpp>
#include <glm/vec3.hpp>
#include <span>

namespace airlight::solid {

// Welded by exact position (−0 = +0), every edge is run by exactly two triangles, once in
// each direction: the mesh bounds a solid, and ray parity means inside.
bool closed(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles);

// Whether p is inside a closed mesh: the parity of the triangles a ray from p crosses, the
// majority over three rays, as one ray through an edge or a vertex may count it twice or not
// at all. Meaningless for an open mesh.
bool inside(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
            const glm::dvec3& p);

// Whether the triangle meets the closed box (touching counts), by separating axes
// (Akenine-Möller 2001: the box's 3 axes, the triangle's normal, the 9 edge products).
bool crosses(const OrientedBox& box, const glm::dvec3& a, const glm::dvec3& b,
             const glm::dvec3& c);

// Whether the box lies inside a closed mesh: no triangle meets it, so it is wholly inside or
// wholly outside, and its centre is inside.
bool box_inside(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles,
                const OrientedBox& box);

}  // namespace airlight::solid
