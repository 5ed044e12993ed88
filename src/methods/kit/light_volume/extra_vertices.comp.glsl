// The light volume mesh's vertices beyond the grid (light_volume_mesh.glsl):
// the apex (spot), or the far ring, skirt and cap corners (directional; texel only).
#include "methods/kit/light_volume/light_volume_mesh.glsl"

void extra_vertices(uint item) {
#if VOLUME_KIND == KIND_SPOT
  extras[0] = vec4(LIGHT.position, 1.0);
#elif VOLUME_KIND == KIND_DIRECTIONAL
  int ring = 4 * grid, k = int(item);
  const vec2 corners[4] = vec2[](vec2(-1.0), vec2(1.0, -1.0), vec2(1.0), vec2(-1.0, 1.0));
  // Under the grid's border, then the skirt's corners, then the cap's: one
  // skirt_extent and one corner read, not one per case (each is compiled).
  vec2 ndc = k < ring ? grid_ndc(border(k)) : corners[max(k - ring, 0) % 4] * skirt_extent();
  float depth = k < ring + 4 ? far_ring_depth : cap_depth;
  extras[k] = vec4(map_point(ndc, depth), 1.0);
#endif
}

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  uint item = uint(first_item) + local;
  extra_vertices(item);
}
