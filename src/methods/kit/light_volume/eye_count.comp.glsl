// The light volume mesh's eye count (light_volume_mesh.glsl): whether the
// frame's eye is inside the light's volume, 0, else 1 (shell: inside the shell,
// 0); and the light's orientation, once, for the triangles that follow.
#include "methods/kit/light_volume/light_volume_mesh.glsl"

// Whether x is on the lit side of the triangle of cell c (of face `face`, on
// vertex layer `layer`) that its NDC position (f: the position within the
// cell, [0, 1]²) falls in: the same split of the cell as grid_triangles, the
// plane of that triangle's corners.
bool below_cell(int face, int layer, ivec2 c, vec2 f, vec3 x) {
  vec3 a, b, d;
  cell_triangle(face, layer, c, f.y <= f.x ? 0 : 1, a, b, d);
  return map_orientation() * dot(cross(b - a, d - a), x - a) < 0.0;
}

// The cell holding NDC ndc ∈ [−1, 1]², and where in it.
ivec2 ndc_cell(vec2 ndc, out vec2 f) {
  vec2 g = (ndc + 1.0) * 0.5 * float(grid);
  ivec2 c = clamp(ivec2(floor(g)), ivec2(0), ivec2(grid - 1));
  f = g - vec2(c);
  return c;
}

// Whether x lies within the map's domain (a cube's: everywhere) on the
// light's side of grid surface `surface` (0: the only or the inner one, 1: a
// shell's outer).
bool below_surface(int surface, vec3 x) {
  vec2 f;
#if VOLUME_KIND == KIND_CUBE
  vec3 v = x - LIGHT.position, a = abs(v);
  if (v == vec3(0.0)) return true;  // at the light: every distance is > 0
  int face;
  vec2 st;
  if (a.x >= a.y && a.x >= a.z) {  // GL's face selection (the major axis)
    face = v.x >= 0.0 ? 0 : 1;
    st = vec2(v.x >= 0.0 ? -v.z : v.z, -v.y) / a.x;
  } else if (a.y >= a.z) {
    face = v.y >= 0.0 ? 2 : 3;
    st = vec2(v.x, v.y >= 0.0 ? v.z : -v.z) / a.y;
  } else {
    face = v.z >= 0.0 ? 4 : 5;
    st = vec2(v.z >= 0.0 ? v.x : -v.x, -v.y) / a.z;
  }
  return below_cell(face, face + surface * FACES, ndc_cell(st, f), f, x);
#else
  vec4 clip = LIGHT.shadow_matrix * vec4(x, 1.0);
  vec2 ndc = clip.xy / clip.w;
  bool domain = clip.w > 0.0 && all(lessThanEqual(abs(ndc), vec2(1.0)));
  return domain && below_cell(0, surface, ndc_cell(ndc, f), f, x);
#endif
}

void eye() {
  vec3 x = frame.eye;
#if DEPTH_MODE == DEPTH_SHELL
  bool inside = !below_surface(0, x) && below_surface(1, x);
#elif VOLUME_KIND == KIND_DIRECTIONAL
  // Inside the skirt's box, and under the grid where the map covers x.
  vec4 clip = LIGHT.shadow_matrix * vec4(x, 1.0);
  vec2 ndc = clip.xy / clip.w;
  float depth = dot(x, LIGHT.direction);
  bool inside = depth > cap_depth && depth < far_ring_depth && all(lessThan(abs(ndc), vec2(skirt_extent())));
  if (inside && all(lessThanEqual(abs(ndc), vec2(1.0)))) inside = below_surface(0, x);
#else
  bool inside = below_surface(0, x);
#endif
  eye_counts[light_index] = inside ? 0 : 1;
}

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  eye();
  extras[ORIENTATION_SLOT] = vec4(map_orientation());  // for the triangles (orientation())
}
