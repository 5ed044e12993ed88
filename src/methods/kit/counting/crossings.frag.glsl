// Per fragment of a counted triangle: where the pixel's ray crosses its plane,
// in front of the visible surface, appended to the pixel's list, so the order
// in which triangles are drawn does not matter. t comes from the exact
// ray–plane intersection, not from interpolated depth. Which pixels' rays
// cross the triangle: for a triangle with finite corners, drawn to cover them
// all (crossings.vert.glsl), the watertight ray test (covers); for one with a
// corner at infinity, the rasterizer, watertight along edges that two
// triangles share. Near-plane clipping is off (GL_DEPTH_CLAMP),
// so crossings between the eye and the near plane count too.
#include "methods/kit/frame/scene.glsl"
#include "methods/kit/counting/crossing_fragment.glsl"

layout(r32ui, binding = 0) uniform coherent uimage2D heads;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  FragmentCrossing x;
  if (!fragment_crossing(x)) return;
  if (!(x.t > 0.0 && x.t < surface_distance(pixel))) return;  // behind the eye, beyond the surface, or grazing (NaN)
  int weight = x.c.light_weight.y;
  uint node = atomicAdd(node_count, 1u);
  if (node >= node_capacity) return;  // counted: the pass runs again with a larger pool
  nodes[3u * node] = floatBitsToUint(x.t);
  nodes[3u * node + 1u] = pack_crossing(x.c.light_weight.x, x.facing > 0.0 ? weight : -weight);
  nodes[3u * node + 2u] = imageAtomicExchange(heads, pixel, node);
}
