#pragma once
// The viewer's camera moves (docs/design.md §5, `view`): orbit about the look-at
// point, fly through the scene, zoom by the field of view. Each takes the
// camera of this frame and returns the next one; they change only the pose
// (position, look_at) and fov_y_deg, never up, near or far. Angles in degrees.
#include <airlight/scene.hpp>
#include <glm/vec3.hpp>

namespace airlight::view {

// Turns the eye about look_at: `yaw` about the camera's up, `pitch` toward it,
// keeping the distance. The elevation stays within ±89° of the horizon (as the
// up vector sees it), so the view never becomes parallel to up.
Camera orbit(const Camera& camera, float yaw_deg, float pitch_deg);

// Turns the view direction about the eye (fly mode's mouse look), with the same
// elevation limit; look_at stays at the same distance in front.
Camera look(const Camera& camera, float yaw_deg, float pitch_deg);

// Moves eye and look_at together by `move` metres in the camera's frame:
// x right, y up, z forward (WASD, Q/E).
Camera fly(const Camera& camera, const glm::vec3& move);

// Moves the eye toward look_at by the factor (0.9: 10 % closer), never onto it.
Camera dolly(const Camera& camera, float factor);

}  // namespace airlight::view
