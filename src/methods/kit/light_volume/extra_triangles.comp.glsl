// The light volume mesh's triangles beyond the grid (light_volume_mesh.glsl):
// the side walls (spot, each cube face's walls across its edges), or walls,
// skirt and cap (directional); shell: the strips between the two surfaces' borders.
#include "methods/kit/light_volume/light_volume_mesh.glsl"

#if DEPTH_MODE == DEPTH_SHELL
// A shell's side (spot: on the frustum's, directional: on the map column's):
// per border segment s the quad between the inner and the outer surface's
// border, two triangles whose edges run against the outer grid's (wound as the
// texel mesh's grid) and the inner grid's (wound the other way).
void extra_triangles(uint item, uint local) {
  int s = int(item);
  float o = orientation(0);
  vec3 i0 = grid_vertex(0, border(s)), i1 = grid_vertex(0, border(s + 1));
  vec3 u0 = grid_vertex(1, border(s)), u1 = grid_vertex(1, border(s + 1));
  write_oriented(2u * local, o, u1, u0, i0);
  write_oriented(2u * local + 1u, o, u1, i0, i1);
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
// On border vertex s, the depth where the two border segments that meet there
// (s − 1 and s) leave their cells' wall to a common side: the nearer cell's
// depth for a spot (its sides run to the apex), the farther for a
// directional map (to the far ring). One corner for both, so the border's
// sides share their edges exactly: overlapping edges of different lengths,
// met by every ray near a spot's apex, let the ray test hold a crossing twice
// or not at all.
float border_end(int s) {
  float before = cell_depth(0, border_cell(s + 4 * grid - 1)), after = cell_depth(0, border_cell(s));
#if VOLUME_KIND == KIND_SPOT
  return min(before, after);
#else
  return max(before, after);
#endif
}

// Part `part` (0, 1) of border segment s's side from the cell's depth d to
// the common ends (border_end): (b1·d, b0·d, b0·e0) and (b1·d, b0·e0, b1·e1),
// no area where an end is d. Returns the ends, b0·e0 and b1·e1, where the
// side goes on to the apex or the far ring.
void border_step(uint index, float o, int s, int part, out vec3 e0, out vec3 e1) {
  float d = cell_depth(0, border_cell(s));
  e0 = corner_at(0, border(s), border_end(s));
  e1 = corner_at(0, border(s + 1), border_end(s + 1));
  vec3 b0 = corner_at(0, border(s), d), b1 = corner_at(0, border(s + 1), d);
  if (part == 0) write_oriented(index, o, b1, b0, e0);
  else if (part == 1) write_oriented(index, o, b1, e0, e1);
}
#endif

// The grid runs along its border from border(s) to border(s + 1) when o > 0:
// what closes it runs back.
void extra_triangles(uint item, uint local) {
  int R = grid, ring = 4 * R, k = int(item);
#if VOLUME_KIND == KIND_CUBE
  // Per face and border segment: the wall to the cell across the cube's edge,
  // from the face of the lower index (the other's: no area).
  int face = k / ring, s = k % ring, other;
  ivec2 cell;
  across_seam(face, s, other, cell);
  float d = cell_depth(face, border_cell(s));
  wall(2u * local, orientation(face), face, border(s), border(s + 1), d, face < other ? cell_depth(other, cell) : d);
#elif VOLUME_KIND == KIND_SPOT
  // Per border segment: its step to the common ends, and from them to the apex.
  float o = orientation(0);
  vec3 e0, e1;
  border_step(local, o, k / 3, k % 3, e0, e1);
  if (k % 3 == 2) write_oriented(local, o, e1, e0, extras[0].xyz);
#elif VOLUME_KIND == KIND_DIRECTIONAL
  float o = orientation(0);
  // [0, 16R): per border segment its step to the common ends E, and walls down
  // from them to the far ring F; [16R, 20R + 4): the skirt at the far depth,
  // per side a fan from its outer corner O; then the outer walls up to the cap
  // corners Q (8), then the cap (2).
  if (k < 4 * ring) {
    int s = k / 4;
    vec3 e0, e1;
    border_step(local, o, s, k % 4, e0, e1);
    vec3 f0 = extras[s].xyz, f1 = extras[(s + 1) % ring].xyz;
    if (k % 4 == 2) write_oriented(local, o, e1, e0, f0);
    else if (k % 4 == 3) write_oriented(local, o, e1, f0, f1);
  } else if (k < 4 * ring + 4 * (R + 1)) {
    int side = (k - 4 * ring) / (R + 1), j = (k - 4 * ring) % (R + 1);
    vec3 outer = extras[ring + side].xyz;
    if (j < R) {
      int s = side * R + j;
      write_oriented(local, o, outer, extras[(s + 1) % ring].xyz, extras[s].xyz);
    } else {
      write_oriented(local, o, extras[((side + 1) * R) % ring].xyz, outer, extras[ring + (side + 1) % 4].xyz);
    }
  } else if (k < 4 * ring + 4 * (R + 1) + 8) {
    int side = (k - 4 * ring - 4 * (R + 1)) / 2;
    vec3 o0 = extras[ring + side].xyz, o1 = extras[ring + (side + 1) % 4].xyz;
    vec3 q0 = extras[ring + 4 + side].xyz, q1 = extras[ring + 4 + (side + 1) % 4].xyz;
    if (k % 2 == 0) write_oriented(local, o, o1, o0, q0);
    else write_oriented(local, o, o1, q0, q1);
  } else {
    vec3 q0 = extras[ring + 4].xyz, q1 = extras[ring + 5].xyz, q2 = extras[ring + 6].xyz, q3 = extras[ring + 7].xyz;
    if (k % 2 == 0) write_oriented(local, o, q0, q3, q2);
    else write_oriented(local, o, q0, q2, q1);
  }
#endif
}
#endif

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  uint item = uint(first_item) + local;
  extra_triangles(item, local);
}
