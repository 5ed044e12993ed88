// The light volume mesh's grid triangles (light_volume_mesh.glsl), one per
// item: texel, six per cell, its flat top and its walls to the next column's
// and row's cells; shell, two per cell and surface.
#include "methods/kit/light_volume/light_volume_mesh.glsl"

#if DEPTH_MODE == DEPTH_SHELL
const int PER_CELL = 4;
#else
const int PER_CELL = 6;
#endif

void grid_triangle(uint item, uint local) {
  int R = grid, t = int(item % uint(PER_CELL)), cell = int(item / uint(PER_CELL));
  int face = cell / (R * R), rest = cell % (R * R);
  ivec2 c = ivec2(rest % R, rest / R);
  float o = orientation();
  vec3 a, b, d;
#if DEPTH_MODE == DEPTH_SHELL
  // t 0, 1: the inner surface, which faces the light (out of the shell); 2, 3 the outer.
  int surface = t / 2;
  cell_triangle(face, face + surface * FACES, c, t % 2, a, b, d);
  o = surface == 0 ? -o : o;
#else
  // The shadow map's own steps: t 0, 1 the texel's flat top, at its depth,
  // over exactly the directions that read it; 2, 3 (4, 5) the wall to the
  // next column's (row's) cell. The last column's and row's walls are the
  // border's sides (extra_triangles): here they get the cell's own depth, no area.
  float dc = cell_depth(face, c);
  ivec2 next = c + (t < 4 ? ivec2(1, 0) : ivec2(0, 1));
  float dn = all(lessThan(next, ivec2(R))) ? cell_depth(face, next) : dc;
  ivec2 u0, u1, u2;
  float d0 = dc, d1 = dc, d2 = dc;
  if (t < 2) half_vertices(t, c, u0, u1, u2);
  else wall_triangle(t < 4 ? c + ivec2(1, 0) : c + ivec2(1), t < 4 ? c + ivec2(1) : c + ivec2(0, 1), dc, dn, t % 2,
                     u0, d0, u1, d1, u2, d2);
  a = corner_at(face, u0, d0);
  b = corner_at(face, u1, d1);
  d = corner_at(face, u2, d2);
#endif
  write_oriented(local, o, a, b, d);
}

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  grid_triangle(uint(first_item) + local, local);
}
