// The light volume mesh's triangles beyond the grid (light_volume_mesh.glsl), one per item:
// the side walls (spot, each cube face's walls across its edges), or walls,
// skirt and cap (directional); shell: the strips between the two surfaces' borders.
#include "methods/kit/light_volume/light_volume_mesh.glsl"

#if DEPTH_MODE == DEPTH_SHELL
// A shell's side (spot: on the frustum's, directional: on the map column's):
// per border segment s the quad between the inner and the outer surface's
// border, two triangles whose edges run against the outer grid's (wound as the
// texel mesh's grid) and the inner grid's (wound the other way).
void extra_triangle(int k, out vec3 a, out vec3 b, out vec3 c) {
  int s = k / 2;
  vec3 i0 = grid_vertex(0, border(s)), i1 = grid_vertex(0, border(s + 1));
  vec3 u0 = grid_vertex(1, border(s)), u1 = grid_vertex(1, border(s + 1));
  a = u1;
  b = k % 2 == 0 ? u0 : i0;
  c = k % 2 == 0 ? i0 : i1;
}
#else
#if VOLUME_KIND == KIND_CUBE
// Border segment s of face `face` (from border(s) to border(s + 1)) lies on a
// cube edge: the other face that holds both ends, and its cell there.
void across_seam(int face, int s, out int other, out ivec2 cell) {
  ivec3 p0 = lattice(face, border(s)), p1 = lattice(face, border(s + 1));
  other = 0;
  for (int g = 0; g < 6; ++g)
    if (g != face && on_face(g, p0) && on_face(g, p1)) other = g;
  cell = min(min(face_coords(other, p0), face_coords(other, p1)), ivec2(grid - 1));
}
#else
// On a border vertex, the depth where the two border segments that meet there
// (their cells' depths `before` and `after`) leave their cells' wall to a
// common side: the nearer cell's depth for a spot (its sides run to the apex),
// the farther for a directional map (to the far ring). One corner for both, so
// the border's sides share their edges exactly: overlapping edges of different
// lengths, met by every ray near a spot's apex, let the ray test hold a
// crossing twice or not at all.
float border_end(float before, float after) {
#if VOLUME_KIND == KIND_SPOT
  return min(before, after);
#else
  return max(before, after);
#endif
}

// Part `part` (0, 1) of border segment s's side from the cell's depth d to
// the common ends (border_end): (b1·d, b0·d, b0·e0) and (b1·d, b0·e0, b1·e1),
// no area where an end is d. Also the ends, e0 = b0·e0 and e1 = b1·e1, where
// the side goes on to the apex or the far ring.
void border_step(int s, int part, out vec3 a, out vec3 b, out vec3 c, out vec3 e0, out vec3 e1) {
  float before = cell_depth(0, border_cell(s + 4 * grid - 1)), d = cell_depth(0, border_cell(s)),
        after = cell_depth(0, border_cell(s + 1));
  e0 = corner_at(0, border(s), border_end(before, d));
  e1 = corner_at(0, border(s + 1), border_end(d, after));
  vec3 b0 = corner_at(0, border(s), d);
  a = corner_at(0, border(s + 1), d);
  b = part == 0 ? b0 : e0;
  c = part == 0 ? e0 : e1;
}
#endif

// Triangle k beyond the grid. The grid runs along its border from border(s)
// to border(s + 1) when its orientation is +1: what closes it runs back.
void extra_triangle(int k, out vec3 a, out vec3 b, out vec3 c) {
  int R = grid, ring = 4 * R;
#if VOLUME_KIND == KIND_CUBE
  // Per face and border segment: the wall to the cell across the cube's edge,
  // from the face of the lower index (the other's: no area), two triangles.
  int face = k / 2 / ring, s = k / 2 % ring, other;
  ivec2 cell;
  across_seam(face, s, other, cell);
  float d = cell_depth(face, border_cell(s));
  ivec2 u0, u1, u2;
  float d0, d1, d2;
  wall_triangle(border(s), border(s + 1), d, face < other ? cell_depth(other, cell) : d, k % 2, u0, d0, u1, d1, u2, d2);
  a = corner_at(face, u0, d0);
  b = corner_at(face, u1, d1);
  c = corner_at(face, u2, d2);
#elif VOLUME_KIND == KIND_SPOT
  // Per border segment: its step to the common ends, and from them to the apex.
  vec3 e0, e1;
  border_step(k / 3, k % 3, a, b, c, e0, e1);
  if (k % 3 == 2) {
    a = e1;
    b = e0;
    c = extras[0].xyz;
  }
#else
  // [0, 16R): per border segment its step to the common ends E, and walls down
  // from them to the far ring F; [16R, 20R + 4): the skirt at the far depth,
  // per side a fan from its outer corner O; then the outer walls up to the cap
  // corners Q (8), then the cap (2). The corners that are extras are read
  // once, by index: a read per case would be a gather per lane for each.
  int ia, ib, ic;
  if (k < 4 * ring) {  // (E1, E0, F0) and (E1, F0, F1): the last two
    int s = k / 4;
    ia = s;
    ib = s;
    ic = k % 4 == 2 ? s : (s + 1) % ring;
  } else if (k < 4 * ring + 4 * (R + 1)) {  // (O, F(s + 1), F(s)); the last: (F, O, O')
    int side = (k - 4 * ring) / (R + 1), j = (k - 4 * ring) % (R + 1), s = side * R + j;
    ia = j < R ? ring + side : ((side + 1) * R) % ring;
    ib = j < R ? (s + 1) % ring : ring + side;
    ic = j < R ? s : ring + (side + 1) % 4;
  } else if (k < 4 * ring + 4 * (R + 1) + 8) {  // (O1, O0, Q0) and (O1, Q0, Q1)
    int side = (k - 4 * ring - 4 * (R + 1)) / 2;
    ia = ring + (side + 1) % 4;
    ib = k % 2 == 0 ? ring + side : ring + 4 + side;
    ic = k % 2 == 0 ? ring + 4 + side : ring + 4 + (side + 1) % 4;
  } else {  // (Q0, Q3, Q2) and (Q0, Q2, Q1)
    ia = ring + 4;
    ib = ring + (k % 2 == 0 ? 7 : 6);
    ic = ring + (k % 2 == 0 ? 6 : 5);
  }
  a = extras[ia].xyz;
  b = extras[ib].xyz;
  c = extras[ic].xyz;
  if (k < 4 * ring) {
    vec3 sa, sb, sc, e0, e1;
    border_step(k / 4, k % 4, sa, sb, sc, e0, e1);
    a = k % 4 < 2 ? sa : e1;
    b = k % 4 < 2 ? sb : k % 4 == 2 ? e0 : b;
    c = k % 4 < 2 ? sc : c;
  }
#endif
}
#endif

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  vec3 a, b, c;
  extra_triangle(first_item + int(local), a, b, c);
  write_oriented(local, orientation(), a, b, c);
}
