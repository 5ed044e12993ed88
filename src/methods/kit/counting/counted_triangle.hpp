#pragma once
// The records crossing counting draws (lit_intervals.glsl CountedTriangle):
// triangles that bound each light's lit region with their weights, their
// planes, and each light's count at the eye with the counted planes through it.
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <cstddef>
#include <vector>

namespace airlight::kit {

// One triangle of a lit region's boundary (lit_intervals.glsl CountedTriangle).
struct CountedTriangle {
  glm::vec4 corners[3];  // homogeneous world positions; w = 0: at infinity
  glm::vec4 plane;       // unit normal n and n·x, computed in double (counted_plane)
  glm::ivec4 light_weight{0};  // light index, weight w
};

// The plane through three homogeneous points (at most one at infinity, which
// then gives the plane's direction), its normal normalized in double and
// oriented as (b − a) × (c − a): in float, a short edge far from the light
// loses the normal's direction, and a crossing's sign with it.
glm::vec4 counted_plane(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c);

// A counted plane through the eye (take_planes_at_eye): a ray crosses it at
// t = 0, by +weight where n·dir > 0.
struct EyePlane {
  glm::vec3 normal;
  int light = 0;
  int weight = 0;
};

// What the resolve starts each ray's counts from: per light, the count at a
// point just off the eye on the negative side of its planes through the eye,
// and those planes (at most max_eye_planes in all).
struct EyeCounts {
  std::vector<int> counts;
  std::vector<EyePlane> planes;
};
inline constexpr int max_eye_planes = 8;  // lit_intervals.comp.glsl's MAX_EYE_PLANES

// Light `light`'s (`source`'s) triangles among triangles[first, end) whose
// plane holds the light's rays, a shadow boundary, and passes through the eye as far as the GPU can tell (within 1e-5 of the coordinates'
// magnitude, float's rounding of the crossing test many times over) with the
// eye inside them: seen edge-on they cover no pixel, and a ray's crossing at
// t ≈ 0 is lost or taken on the side float rounding picks (random scene 31:
// the eye on a shadow plane, the shadow on the wrong side of a line through
// the image). Their weights become 0 and they are returned, with in `beside` a
// point off the eye on the negative side of all of them, where the caller
// counts; none when there are none, or more than `room`, or no such point is
// found (then they are left as they were). Triangles through the eye with the
// eye outside them are crossed by no ray from it: their weights become 0 too.
std::vector<EyePlane> take_planes_at_eye(std::vector<CountedTriangle>& triangles, size_t first, int light,
                                         const Light& source, const glm::dvec3& eye, size_t room, glm::dvec3& beside);

}  // namespace airlight::kit
