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
void set_next(uint node, uint next) { nodes[3u * node + 2u] = next; }

// The order of events: by t, ties (whose order does not matter) by node index.
bool before(uint a, uint b) {
  float ta = node_t(a), tb = node_t(b);
  return ta < tb || (ta == tb && a < b);
}

// The pixel's list sorted in place, in that order: a bottom-up merge sort of
// the linked list (runs of 1, 2, 4, … merged pass by pass), about 2n·log₂n
// iterations for n crossings. Picking each light's next event from the whole
// list instead took n per event, n² in all, which llvmpipe's loop limit cut
// short at a few hundred crossings (docs/decisions.md, Numerics).
uint sorted(uint head) {
  uint list = head;
  // Runtime bounds: the list's length (passes end when one merge was enough).
  for (uint run = 1u; list != END_OF_LIST; run *= 2u) {
    uint p = list, tail = END_OF_LIST;
    list = END_OF_LIST;
    int merges = 0;
    while (p != END_OF_LIST) {
      ++merges;
      uint q = p, p_size = 0u, q_size = run;
      while (p_size < run && q != END_OF_LIST) {
        ++p_size;
        q = node_next(q);
      }
      while (p_size > 0u || (q_size > 0u && q != END_OF_LIST)) {
        bool from_p = q_size == 0u || q == END_OF_LIST || (p_size > 0u && before(p, q));
        uint e = from_p ? p : q;
        if (from_p) {
          p = node_next(p);
          --p_size;
        } else {
          q = node_next(q);
          --q_size;
        }
        if (tail == END_OF_LIST) list = e;
        else set_next(tail, e);
        tail = e;
      }
      p = q;
    }
    set_next(tail, END_OF_LIST);
    if (merges <= 1) break;
  }
  return list;
}

// Light i's first event at or after `node` in the sorted list, or END_OF_LIST.
uint next_event(int i, uint node) {
  // Runtime bounds: the crossings along this ray.
  for (; node != END_OF_LIST; node = node_next(node))
    if (crossing_light(nodes[3u * node + 1u]) == i) break;
  return node;
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
  vec3 sum = vec3(0.0);
  for (uint node = next_event(i, head); node != END_OF_LIST; node = next_event(i, node_next(node))) {
    float t = node_t(node);
    int after = count + crossing_change(nodes[3u * node + 1u]);
    if (count <= 0 && after > 0) sum += lit_gamma(i, eye, dir, start, t);
    if (count > 0 && after <= 0) start = t;
    count = after;
  }
  if (count <= 0) sum += lit_gamma(i, eye, dir, start, d);
  return sum;
}

#ifdef LOOP_LIMIT
// llvmpipe ends an invocation's loops once their iterations, summed over all of
// them, reach LOOP_LIMIT (docs/decisions.md, Numerics): a pixel with many
// crossings lost the end of its sum, silently. For n crossings, its sort costs
// about 2n·log₂n iterations, its walks 2n per light, and each of at most
// n + lights lit intervals about GAMMA_ITERATIONS per piece for Γ (Biri's
// panels) and SAMPLE_ITERATIONS per correction sample (the media's and lobes'
// loops in it), both set from where the limit was seen to bite; the samples
// per interval are lowered to what fits in 7/8 of the limit. The limit
// counts a SIMD batch's loops, which run while any of its pixels needs them:
// n is the longest list of the work group, which holds the batch. Every
// invocation of the group calls this (barriers).
const int GAMMA_ITERATIONS = 64, SAMPLE_ITERATIONS = 8;
shared int longest_list;
void fit_loop_limit(uint head) {
  int own = 0;
  for (uint node = head; node != END_OF_LIST; node = node_next(node)) ++own;
  if (gl_LocalInvocationIndex == 0u) longest_list = 0;
  barrier();
  atomicMax(longest_list, own);
  barrier();
  int n = longest_list, intervals = n + LIGHT_COUNT;
  int left = LOOP_LIMIT / 8 * 7 - n * (2 * (findMSB(n) + 1) + 2 * LIGHT_COUNT + 1) -
             intervals * GAMMA_ITERATIONS * (2 * VOLUME_COUNT + 1);
  correction_samples = clamp(left / (intervals * SAMPLE_ITERATIONS), 1, SAMPLES);
}

// Whether the limit was reached all the same: once it is, every loop ends
// after one iteration, and this one, of two, would end after one.
bool loop_limit_reached(uint head) {
  int iterations = 0;
  for (int k = 0; k < 2 + int(head == END_OF_LIST - 1u); ++k) ++iterations;  // a bound the compiler can't fold
  return iterations < 2;
}
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  bool inside = all(lessThan(pixel, frame_size()));
  uint list = inside ? imageLoad(heads, pixel).r : END_OF_LIST;
#ifdef LOOP_LIMIT
  fit_loop_limit(list);
#endif
  if (!inside) return;
  list = sorted(list);
  load_scene();
  vec3 dir = pixel_ray(vec2(pixel) + 0.5);
  float d = surface_distance(pixel);
  cut_into_pieces(dir, d);
  vec3 sum = vec3(0.0);
#define ADD_LIGHT(i) sum += light_airlight(i, list, dir, d);
  FOR_EACH_LIGHT(ADD_LIGHT)
#undef ADD_LIGHT
#ifdef LOOP_LIMIT
  if (loop_limit_reached(list)) atomicAdd(loop_limited, 1u);
#endif
  imageStore(airlight_out, pixel, vec4(sum, 1.0));
}
