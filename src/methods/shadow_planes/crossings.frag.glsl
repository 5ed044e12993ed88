// Per fragment of a shadow plane: where the pixel's ray crosses the plane, in
// front of the visible surface, appended to the pixel's list (Biri §4.2 sums
// Γ over the lit intervals; here they are resolved per pixel by counting, so
// the order in which planes are drawn does not matter). t comes from the exact
// ray–plane intersection, not from interpolated depth; the rasterizer only
// decides which pixels' rays cross the quad, and does so watertight along
// edges that two planes share. Near-plane clipping is off (GL_DEPTH_CLAMP),
// so crossings between the eye and the near plane count too.
#include "methods/kit/scene.glsl"
#include "methods/shadow_planes/crossings.glsl"

layout(r32ui, binding = 0) uniform coherent uimage2D heads;

flat in int plane;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 dir = pixel_ray(gl_FragCoord.xy);
  ShadowPlane p = planes[plane];
  int i = int(p.b.w);
  float facing = dot(p.plane.xyz, dir);
  float t = (p.plane.w - dot(p.plane.xyz, frame.eye)) / facing;
  if (!(t > 0.0 && t < surface_distance(pixel))) return;  // behind the eye, beyond the surface, or grazing (NaN)
  int weight = int(p.a.w);
  uint node = atomicAdd(node_count, 1u);
  if (node >= node_capacity) return;  // counted: the pass runs again with a larger pool
  nodes[3u * node] = floatBitsToUint(t);
  nodes[3u * node + 1u] = pack_crossing(i, facing > 0.0 ? weight : -weight);
  nodes[3u * node + 2u] = imageAtomicExchange(heads, pixel, node);
}
