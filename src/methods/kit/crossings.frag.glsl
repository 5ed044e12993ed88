// Per fragment of a counted triangle: where the pixel's ray crosses its plane,
// in front of the visible surface, appended to the pixel's list, so the order
// in which triangles are drawn does not matter. t comes from the exact
// ray–plane intersection, not from interpolated depth. Which pixels' rays
// cross the triangle: for a triangle drawn grown (crossings.vert.glsl), the
// watertight ray test (covers); otherwise the rasterizer, watertight along
// edges that two triangles share. Near-plane clipping is off (GL_DEPTH_CLAMP),
// so crossings between the eye and the near plane count too.
#include "methods/kit/scene.glsl"
#include "methods/kit/lit_intervals.glsl"

layout(r32ui, binding = 0) uniform coherent uimage2D heads;

flat in int triangle;
flat in int exact;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 dir = pixel_ray(gl_FragCoord.xy);
  CountedTriangle c = counted[triangle];
  if (!covers(exact, c, dir)) return;
  float facing = dot(c.plane.xyz, dir);
  float t = (c.plane.w - dot(c.plane.xyz, frame.eye)) / facing;
  if (!(t > 0.0 && t < surface_distance(pixel))) return;  // behind the eye, beyond the surface, or grazing (NaN)
  int weight = c.light_weight.y;
  uint node = atomicAdd(node_count, 1u);
  if (node >= node_capacity) return;  // counted: the pass runs again with a larger pool
  nodes[3u * node] = floatBitsToUint(t);
  nodes[3u * node + 1u] = pack_crossing(c.light_weight.x, facing > 0.0 ? weight : -weight);
  nodes[3u * node + 2u] = imageAtomicExchange(heads, pixel, node);
}
