// The light volume mesh's grid triangles (light_volume_mesh.glsl): texel, six
// per cell, its flat top and its walls to the next column's and row's cells;
// shell, two per cell and surface.
#include "methods/kit/light_volume/light_volume_mesh.glsl"

// Cell c's two triangles on vertex layer `layer`, from record `index`.
void cell_triangles(uint index, float o, int face, int layer, ivec2 c) {
  vec3 v00, v10, v01, v11;
  cell_corners(face, layer, c, v00, v10, v01, v11);
  write_oriented(index, o, v00, v10, v11);
  write_oriented(index + 1u, o, v00, v11, v01);
}


void grid_triangles(uint item, uint local) {
  int R = grid;
  int face = int(item / uint(R * R)), rest = int(item % uint(R * R));
  ivec2 c = ivec2(rest % R, rest / R);
  float o = orientation(face);
#if DEPTH_MODE == DEPTH_SHELL
  cell_triangles(4u * local, -o, face, face, c);  // the inner surface faces the light: out of the shell
  cell_triangles(4u * local + 2u, o, face, face + FACES, c);
#else
  // The shadow map's own steps: the texel's flat top, at its depth, over
  // exactly the directions that read it, and the walls to the next column's
  // and row's cells. The last column's and row's walls are the border's
  // sides (extra_triangles): here they get the cell's own depth, no area.
  cell_triangles(6u * local, o, face, face, c);
  float d = cell_depth(face, c);
  float right = c.x + 1 < R ? cell_depth(face, c + ivec2(1, 0)) : d;
  float up = c.y + 1 < R ? cell_depth(face, c + ivec2(0, 1)) : d;
  wall(6u * local + 2u, o, face, c + ivec2(1, 0), c + ivec2(1), d, right);
  wall(6u * local + 4u, o, face, c + ivec2(1), c + ivec2(0, 1), d, up);
#endif
}

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  uint item = uint(first_item) + local;
  grid_triangles(item, local);
}
