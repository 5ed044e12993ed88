#pragma once
// The polygons that close a light's influence volume for a beam tree
// (beam_tree.hpp): every beam of the light ends on one of them.
#include "geometry/beam_tree.hpp"

#include <airlight/scene.hpp>
#include <vector>

namespace airlight::geometry {

// The backplate of the light's influence volume (§3.2.1, Nilsson's "visible polygons of the
// backplate"), so that every beam of light ends on a polygon: a point light's cube of
// half-size far_distance around L (six faces); a spot's base at far_distance along its axis
// circumscribing the cone when cone_deg ≤ 45°, else the faces of that cube (in the spot's
// frame) that the cone reaches; a beam's far face (aperture, length); an unbounded
// directional light's square of half-size far_distance at far_distance downstream of the
// origin, which closes every beam through the ball of radius far_distance about the origin.
// Every face has source -1.
std::vector<BeamPolygon> influence_backplate(const Light& light, double far_distance);

}  // namespace airlight::geometry
