// The light volume mesh's cell depths (shell only; light_volume_mesh.glsl):
// each grid cell's [min, max] stored depth, over its texels, or (CELL_SPLIT)
// over one 64² sub-block of them, merged by atomics.
#include "methods/kit/light_volume/light_volume_mesh.glsl"

void cells(uint item) {
  int R = grid, S = map_size;
#ifdef CELL_SPLIT
  uint per_cell = uint(sub_blocks * sub_blocks);
  uint cell = item / per_cell, sub = item % per_cell;
#else
  uint cell = item;
#endif
  int face = int(cell / uint(R * R)), rest = int(cell % uint(R * R));
  ivec2 c = ivec2(rest % R, rest / R);
  ivec2 lo = c * S / R, hi = ((c + 1) * S + R - 1) / R;  // the texels the cell overlaps
#ifdef CELL_SPLIT
  lo += ivec2(int(sub) % sub_blocks, int(sub) / sub_blocks) * CELL_BLOCK;
  hi = min(hi, lo + CELL_BLOCK);
#endif
  float low = positive_infinity(), high = -positive_infinity();
  for (int y = lo.y; y < hi.y; ++y)
    for (int x = lo.x; x < hi.x; ++x) {
      float d = clamp_depth(stored_depth(face, ivec2(x, y)));
      low = min(low, d);
      high = max(high, d);
    }
  ivec3 at = ivec3(c, face);
#ifdef CELL_SPLIT
  if (lo.x < hi.x && lo.y < hi.y) {
    imageAtomicMin(cell_low, at, order_bits(low));
    imageAtomicMax(cell_high, at, order_bits(high));
  }
#else
  imageStore(cell_low, at, uvec4(order_bits(low)));
  imageStore(cell_high, at, uvec4(order_bits(high)));
#endif
}

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  uint item = uint(first_item) + local;
  cells(item);
}
