#pragma once
// Where each light's shadow map looks (docs/design.md §3): which kind of map a
// light gets, and the projection of a 2D map or a cube's faces, fitted to the
// bounds of the casters as this frame places them (caster_bounds.hpp) — or
// read off an engine's own map (engine_projection.hpp).
#include "methods/kit/frame/shadows/caster_bounds.hpp"

#include <airlight/engine.hpp>
#include <airlight/scene.hpp>
#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace airlight::kit {

// SceneLight.shadow_kind (scene.glsl's SHADOW_*).
enum ShadowKind { shadow_none = 0, shadow_map = 1, shadow_cube = 2 };

// Half-angle from which a spot light gets a cube map instead of a 2D map: a 2D
// map of field 2·cone has texels tan(cone) times coarser at its centre than a cube
// face (90°); at 60° that is 1.7×, and it diverges toward 90°.
inline constexpr float wide_spot_deg = 60.0f;

// The map an engine gives the light, else none where nothing can occlude, a
// cube for point lights and spots from wide_spot_deg, a 2D map otherwise.
int shadow_kind(const Light& light, const Bounds& bounds, const EngineShadow* engine);

// World → clip of a 2D map, and a texel's world size at distance r:
// (per_distance·r + constant) / resolution.
struct Projection {
  glm::mat4 matrix{1.0f};
  float per_distance = 0.0f, constant = 0.0f;
};

// A spot's cone in a square perspective map of field 2·cone.
Projection spot_projection(const Light& light, const Bounds& bounds);
// A directional light orthographically, over the scene's bounds or a beam's aperture.
Projection directional_projection(const Light& light, const Bounds& bounds);
// A point light's (or wide spot's) six faces in GL's order.
std::array<glm::mat4, 6> cube_face_matrices(const glm::dvec3& apex, const Bounds& bounds);

}  // namespace airlight::kit
