// Per pixel, L_air = Σ_lights Σ over the lit intervals [a, b] of the view ray
// of Γ(a → b), the closed-form airlight (closed_form.glsl, the twin of
// optics::gamma): Biri 2006 §4.2 (shadow_planes) and Nilsson 2008 §3.2
// (beam_volumes) sum it over the same intervals.
//
// The lit intervals come from counting (lit_intervals.glsl): light i's count
// starts at the eye's (computed on the CPU per frame) and changes by each
// crossing's signed weight in the order of t; the ray is lit by i where the
// count is 0 (or less). Counting is exact whatever the order or nesting of the volumes
// and wherever the eye is, which Biri gets from drawing back to front with the
// stencil; here each light walks the pixel's crossings in the order of t
// (next_event). Crossings at equal t give empty intervals, whose Γ is 0.
//
// Gobos and bounded volumes: lit_gamma.glsl.
#define SCENE_IN_REGISTERS
#include "methods/kit/lit_gamma.glsl"
#include "methods/kit/lit_intervals.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) writeonly uniform image2D airlight_out;
layout(r32ui, binding = 1) readonly uniform uimage2D heads;

uniform int eye_counts[LIGHT_COUNT > 0 ? LIGHT_COUNT : 1];  // each light's count at the eye (GLSL has no empty arrays)


float node_t(uint node) { return uintBitsToFloat(nodes[3u * node]); }
uint node_next(uint node) { return nodes[3u * node + 2u]; }

// The event of light i that follows (t, node) in the order of (t, node index),
// or END_OF_LIST: a selection from the pixel's whole list, which is read, never
// rewritten (lists are short; ties in t, whose order does not matter, are
// broken by the node index).
uint next_event(int i, uint head, float t, uint node) {
  float best_t = positive_infinity();
  uint best = END_OF_LIST;
  // Runtime bounds: the list's length is the data (crossings along this ray).
  for (uint n = head; n != END_OF_LIST; n = node_next(n)) {
    float tn = node_t(n);
    bool later = tn > t || (tn == t && n > node);
    bool earlier = tn < best_t || (tn == best_t && n < best);
    if (crossing_light(nodes[3u * n + 1u]) == i && later && earlier) {
      best_t = tn;
      best = n;
    }
  }
  return best;
}

// Light i along [0, d]: Γ over the stretches where its count is 0 or less.
// Counts are never below 0 in exact arithmetic (shadow volumes contain a
// point a non-negative number of times; the lit pyramids of a beam tree do
// not overlap); where pyramids overlap by their ε-thick planes, a point is in
// two and the count reads −1, which is lit all the same.
vec3 light_airlight(int i, uint head, vec3 dir, float d) {
  vec3 eye = frame.eye;
  int count = eye_counts[i];
  float start = 0.0;  // where the current lit stretch began (when count <= 0)
  float t = -1.0;     // the last event: before every crossing (all have t > 0)
  vec3 sum = vec3(0.0);
  // Runtime bounds: the crossings along this ray.
  for (uint node = next_event(i, head, t, 0u); node != END_OF_LIST; node = next_event(i, head, t, node)) {
    t = node_t(node);
    int after = count + crossing_change(nodes[3u * node + 1u]);
    if (count <= 0 && after > 0) sum += lit_gamma(i, eye, dir, start, t);
    if (count > 0 && after <= 0) start = t;
    count = after;
  }
  if (count <= 0) sum += lit_gamma(i, eye, dir, start, d);
  return sum;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, frame_size()))) return;
  load_scene();
  vec3 dir = pixel_ray(vec2(pixel) + 0.5);
  float d = surface_distance(pixel);
  uint list = imageLoad(heads, pixel).r;
  cut_into_pieces(dir, d);
  vec3 sum = vec3(0.0);
#define ADD_LIGHT(i) sum += light_airlight(i, list, dir, d);
  FOR_EACH_LIGHT(ADD_LIGHT)
#undef ADD_LIGHT
  imageStore(airlight_out, pixel, vec4(sum, 1.0));
}
