// The light volume mesh's grid vertices (light_volume_mesh.glsl): the (R+1)²
// vertices per map or cube face — texel: each corner's ray (origin and step
// per unit depth) and the depth of the cell it is the first corner of; shell:
// the displaced vertices of both surfaces.
#include "methods/kit/light_volume/light_volume_mesh.glsl"

#if DEPTH_MODE == DEPTH_SHELL
// The largest angle, seen from the light, between two corners of a grid cell:
// its diagonal at the map's (or face's) centre, where a rectilinear map's
// cells are widest.
float cos_widest_cell() {
#if VOLUME_KIND == KIND_CUBE
  return 1.0 / sqrt(1.0 + 8.0 / float(grid * grid));
#else
  return dot(normalize(map_ray(vec2(0.0))), normalize(map_ray(vec2(2.0 / float(grid)))));
#endif
}

// One texel past `stored`, a texel's size there being (k·r + c)/S: the shell's
// outer grid keeps that thickness where its cells' texels agree, so its
// surface stays a closed two-manifold (inner and outer would meet there); a
// shell that grows stays conservative.
float past_texel(float stored) {
  float b = 1.0 / frame.shadow_resolution;
#if VOLUME_KIND == KIND_DIRECTIONAL
  return stored + b * LIGHT.texel_constant;
#else
  return (stored + b * LIGHT.texel_constant) / max(1.0 - b * LIGHT.texel_per_distance, 1e-6);
#endif
}

// An outer vertex's distance, from the farthest stored depth of its cells
// (where the shadow test stops calling points lit): a texel past it, and for a
// light at a point past the chords between a cell's corners: a point of a
// triangle whose corners lie at distances ≥ D, at angles ≤ α apart as seen
// from the light, is at distance ≥ D·cos α (its projection on one corner's
// direction). An inner vertex needs neither: a triangle whose corners lie
// within distance D of the light lies within it (the ball is convex).
float beyond_lit(float stored) {
#if VOLUME_KIND == KIND_DIRECTIONAL
  return past_texel(stored);
#else
  return past_texel(stored) / cos_widest_cell();
#endif
}

// The extremes of the stored depths over the cells of `face` around vertex v.
void gather_cells(int face, ivec2 v, inout float low, inout float high) {
  ivec2 lo = max(v - 1, ivec2(0)), hi = min(v, ivec2(grid - 1));
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      low = min(low, from_order_bits(imageLoad(cell_low, ivec3(x, y, face)).r));
      high = max(high, from_order_bits(imageLoad(cell_high, ivec3(x, y, face)).r));
    }
}
#endif

void grid_vertices(uint item) {
  int n = grid + 1;
  int face = int(item / uint(n * n)), rest = int(item % uint(n * n));
  ivec2 v = ivec2(rest % n, rest / n);
  ivec3 p = lattice(face, v);
#if VOLUME_KIND == KIND_CUBE && DEPTH_MODE == DEPTH_SHELL
  if (owner(p) != face) return;  // another face computes this edge or corner vertex
#endif
#if DEPTH_MODE == DEPTH_TEXEL
  // grid_position as origin + depth · step (corner_at).
#if VOLUME_KIND == KIND_CUBE
  vec3 step = normalize(vec3(2 * p - grid) / float(grid));
#elif VOLUME_KIND == KIND_SPOT
  vec3 step = normalize(map_ray(grid_ndc(v)));
#else
  vec3 along = map_ray(grid_ndc(v)), step = along / dot(along, LIGHT.direction), origin = map_point(grid_ndc(v), 0.0);
#endif
  imageStore(vertices, ivec3(v, face), vec4(step, all(lessThan(v, ivec2(grid))) ? map_cell_depth(face, v) : 0.0));
#if VOLUME_KIND == KIND_DIRECTIONAL
  imageStore(vertices, ivec3(v, face + FACES), vec4(origin, 1.0));
#endif
#else
  float low = positive_infinity(), high = -positive_infinity();
#if VOLUME_KIND == KIND_CUBE
  // Every cell around the lattice point, on every face that holds it (constant faces: unrolled).
#define GATHER_FACE(f) if (on_face(f, p)) gather_cells(f, face_coords(f, p), low, high);
  GATHER_FACE(0) GATHER_FACE(1) GATHER_FACE(2) GATHER_FACE(3) GATHER_FACE(4) GATHER_FACE(5)
#undef GATHER_FACE
#else
  gather_cells(0, v, low, high);
#endif
  imageStore(vertices, ivec3(v, face), vec4(grid_position(v, p, low), 1.0));
  imageStore(vertices, ivec3(v, face + FACES), vec4(grid_position(v, p, beyond_lit(high)), 1.0));
#endif
}

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  uint item = uint(first_item) + local;
  grid_vertices(item);
}
