// A sparse grid's tiles (SceneFrame::use_grid): the indirect dispatch's
// workgroup counts, then each 8×8 tile's corner, a tile per workgroup of
// gpu::pixel_workgroup (tile gl_WorkGroupID.y · TILE_ROW + gl_WorkGroupID.x).
// Written by methods/kit/resolution, read by pixel.glsl. Needs BINDING_TILES.
const uint TILE_ROW = 4096u;
#ifdef TILES_READONLY
readonly
#endif
layout(std430, binding = BINDING_TILES) buffer FrameTiles {
  uvec4 tile_groups;  // x, y, z workgroups; w the number of tiles
  uvec2 tile_corner[];
};

#ifndef TILES_READONLY
// A flag per 8×8 tile of the frame, cleared before the tiles are listed.
layout(std430, binding = BINDING_TILE_FLAGS) buffer TileFlags { uint tile_flag[]; };

// Lists the tile of `pixel` in a frame `width` pixels wide, once however
// many of its pixels call it (atomics, not a barrier: llvmpipe runs a
// barrier's two halves as coroutines, which costs a pass several times over).
void list_tile(ivec2 pixel, int width) {
  uvec2 tile = uvec2(pixel) / 8u;
  uint index = tile.y * uint((width + 7) / 8) + tile.x;
  if (atomicOr(tile_flag[index], 1u) == 0u) tile_corner[atomicAdd(tile_groups.w, 1u)] = tile * 8u;
}
#endif

// This invocation's pixel in its tile; (−1, −1) past the last tile.
ivec2 tile_pixel() {
  uint tile = gl_WorkGroupID.y * TILE_ROW + gl_WorkGroupID.x;
  return tile < tile_groups.w ? ivec2(tile_corner[tile] + gl_LocalInvocationID.xy) : ivec2(-1);
}
