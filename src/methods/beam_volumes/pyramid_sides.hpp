#pragma once
// The sides of the lit pyramids (lit_pyramids.hpp) that no neighbour cancels
// edge for edge, summed plane by plane into the lit region's own boundary.
//
// At a step in depth seen from the light — an occluder's edge in front of the
// surface its shadow falls on — the two pyramids' sides lie in one plane
// through the light, wound opposite ways, each from the light out to its own
// piece: they overlap from the light to the nearer piece, where they cancel.
// Near the light's image in view they are slivers that the float ray test
// decides each on its own, and a lost one flipped the count along the rest of
// the ray (docs/decisions.md, "Beam volumes"). Summed, the sides of a plane
// leave the band between the nearer and the farther pieces (a shadow plane
// from the occluder to the surface behind it), and nothing reaches the light
// where the pieces tile its view.
#include "geometry/conforming_set.hpp"

#include <array>
#include <glm/vec4.hpp>
#include <vector>

namespace airlight::methods {

// A pyramid's side: the triangle (b, a, apex) over its base's edge a → b, wound out of the pyramid.
struct PyramidSide {
  int a = 0, b = 0;  // vertices of the conforming set
};

// A triangle of the boundary that counts `weight` crossings, wound as its plane faces.
struct WeightedTriangle {
  std::array<glm::dvec4, 3> corners;
  int weight = 1;
};

// apex: the light's position (w = 1), or the direction back toward a directional light
// (w = 0). Ends seen from a point light along one line of sight, and sides in one plane
// through it, are taken as such within `tolerance` (the beam tree's ε) at `reach` from it (the
// farthest caster: the backplate lies far beyond, and there ε is finer than the input's
// rounding); across a directional light, within the tolerance. The triangles' weighted sum is
// the sides' sum (as 2-chains, exactly).
std::vector<WeightedTriangle> summed_sides(const geometry::ConformingSet& set, const std::vector<PyramidSide>& sides,
                                           const glm::dvec4& apex, double reach, double tolerance);

}  // namespace airlight::methods
