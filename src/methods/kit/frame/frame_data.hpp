#pragma once
// The C++ side of methods/kit/frame/frame_data.glsl: the same struct text, compiled
// with GLSL's type names mapped to glm's, and its layout checked against the
// std140 / std430 offsets the shaders use.
#include <cstddef>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace airlight::kit::shader {

using vec2 = glm::vec2;
using vec3 = glm::vec3;
using mat4 = glm::mat4;

#include "methods/kit/frame/frame_data.glsl"

static_assert(sizeof(vec3) == 12 && alignof(vec3) == 4 && sizeof(mat4) == 64);
static_assert(offsetof(FrameData, eye) == 64 && offsetof(FrameData, near_plane) == 76);
static_assert(offsetof(FrameData, size) == 176 && offsetof(FrameData, light_model) == 188);
static_assert(offsetof(FrameData, light_count) == 192 && sizeof(FrameData) == 208);
static_assert(offsetof(SceneLight, shadow_matrix) == 80 && offsetof(SceneLight, type) == 144);
static_assert(offsetof(SceneLight, texel_per_distance) == 160 && sizeof(SceneLight) == 176);
static_assert(offsetof(SceneVolume, hi) == 16 && offsetof(SceneVolume, sigma_t) == 48 && sizeof(SceneVolume) == 64);
static_assert(sizeof(SceneLobe) == 16);

}  // namespace airlight::kit::shader
