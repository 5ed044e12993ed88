// sv_march's bounds (Kingston 2018 §4.3.2): per pixel and light, the nearest
// and the farthest crossing of the pixel's ray with the light's shell mesh
// (crossings.vert.glsl draws its faces), by atomic min and max on the
// distance's bits (t > 0: its bits order as the floats). Layer 2i holds light
// i's front, cleared to +∞; layer 2i + 1 its back, cleared to 0. A crossing
// beyond the visible surface says the ray ends inside the shell: the back
// clamps to the surface's distance.
#include "methods/kit/frame/scene.glsl"
#include "methods/kit/counting/crossing_fragment.glsl"

layout(r32ui, binding = 0) uniform coherent uimage2DArray bounds;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  FragmentCrossing x;
  if (!fragment_crossing(x)) return;
  float t = x.t;
  if (!(t > 0.0)) return;  // behind the eye, or grazing (NaN): whether the eye is in the shell decides (sv_march.comp.glsl)
  float d = surface_distance(pixel);
  int layer = 2 * x.c.light_weight.x;
  if (t < d) imageAtomicMin(bounds, ivec3(pixel, layer), floatBitsToUint(t));
  imageAtomicMax(bounds, ivec3(pixel, layer + 1), floatBitsToUint(min(t, d)));
}
