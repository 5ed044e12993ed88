#pragma once
#include "gpu/gl.hpp"

#include <string>

namespace airlight::kit {

// Binding points of the frame's buffers and textures, shared with GLSL through
// SceneFrame::defines() (scene.glsl uses the BINDING_* macros). Methods use image unit
// 0 for their output and texture units / storage bindings from the first_free_*.
namespace binding {
inline constexpr GLuint frame_block = 0;     // uniform block FrameBlock (std140)
inline constexpr GLuint lights = 0;          // SSBO SceneLight[] (std430)
inline constexpr GLuint volumes = 1;         // SSBO SceneVolume[]
inline constexpr GLuint lobes = 2;           // SSBO SceneLobe[] (medium's, then each volume's)
inline constexpr GLuint face_normals = 3;    // SSBO vec4[] per triangle (G-buffer pass only)
inline constexpr GLuint objects = 4;         // SSBO ObjectTransform[] per mesh (G-buffer and shadow passes)
inline constexpr GLuint pixel_list = 5;      // SSBO PixelList of a sparse grid (pixel.glsl)
inline constexpr GLuint first_free_storage = 8;
inline constexpr GLuint distance = 0;        // sampler2D R32F: eye distance along the pixel ray
inline constexpr GLuint normal = 1;          // sampler2D RGBA32F: shading normal, facing the eye
inline constexpr GLuint geometric_normal = 2; // sampler2D RGBA32F: triangle normal, facing the eye
inline constexpr GLuint albedo = 3;          // sampler2D RGBA32F: rgb albedo, a = 1 where a surface is hit
inline constexpr GLuint gobos = 4;           // sampler2DArray RGBA32F, one layer per gobo
inline constexpr GLuint shadow_maps = 5;     // sampler2DArray R32F, one layer per 2D shadow map
inline constexpr GLuint shadow_cubes = 6;    // samplerCubeArray R32F, one cube per point / wide spot
inline constexpr GLuint engine_input = 7;    // an engine's depth or shadow texture while it is converted
inline constexpr GLuint first_free_texture = 8;
}  // namespace binding

// "#define BINDING_… n" for every binding point.
std::string binding_defines();

}  // namespace airlight::kit
