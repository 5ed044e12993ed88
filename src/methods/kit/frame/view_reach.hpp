#pragma once
// How far a frame sees, for what must lie past everything it can see: the
// backplate of beam_volumes' lit pyramids and the far end of the light
// volumes (docs/design.md §3).
#include <airlight/method.hpp>
#include <glm/vec3.hpp>

namespace airlight::kit {

// How far from the eye the frame sees: its far plane along the image's corner
// rays (geometry::corner_distance), for a frame of aspect W/H.
double view_reach(const FrameInputs& inputs);

// A distance from a light at `light` past every point the frame can see, in
// the scene's own scale: 2·(|eye − light| + view_reach) (beam_volumes'
// backplate, the light volumes' far depth). An added metre put a millimetre
// scene's backplate 40 times past its far plane, and beam_volumes lost its
// crossings beside the light (random scenes 307, 496, 741, 854, 904, 939,
// 952; 939 fails again at 40 times this distance); the far plane's depth in
// place of the corner rays' reach put it inside a wide view (seed 391).
double beyond_view(const FrameInputs& inputs, const glm::dvec3& light);

}  // namespace airlight::kit
