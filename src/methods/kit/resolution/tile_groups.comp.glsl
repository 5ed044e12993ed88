// The indirect dispatch of a sparse grid's tiles (tiles.glsl): TILE_ROW
// workgroups a row, as many rows as the tiles fill.
#include "methods/kit/frame/tiles.glsl"

layout(local_size_x = 1) in;

void main() {
  uint tiles = tile_groups.w;
  tile_groups.xyz = uvec3(min(tiles, TILE_ROW), (tiles + TILE_ROW - 1u) / TILE_ROW, 1u);
}
