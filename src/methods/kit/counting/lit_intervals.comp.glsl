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
#include "methods/kit/frame/pixel.glsl"
#include "methods/kit/gamma/lit_gamma.glsl"
#include "methods/kit/counting/lit_intervals.glsl"

#ifdef LOOP_LIMIT
layout(rgba32f, binding = 0) uniform image2D airlight_out;  // passes add to it
layout(r32ui, binding = 1) uniform uimage2D heads;          // the first pass sorts the lists
#else
layout(rgba32f, binding = 0) writeonly uniform image2D airlight_out;
layout(r32ui, binding = 1) readonly uniform uimage2D heads;
#endif

uniform int eye_counts[LIGHT_COUNT > 0 ? LIGHT_COUNT : 1];  // each light's count at the eye (GLSL has no empty arrays)
#ifdef EYE_PLANES
// The counted planes through the eye (lit_interval_pass.hpp, take_planes_at_eye):
// xyz the normal, w the light; a ray crosses one at t = 0, by its weight where
// n·dir > 0. Uniforms, not defines: an eye on a plane for one frame must not
// compile the program again. Only a geometry that may have such planes
// (CrossingGeometry::has_eye_planes) compiles their loop: on llvmpipe each
// light structure's copy of it cost about 0.1 s of the first dispatch
// (docs/decisions.md "The first frame (issue 28)").
const int MAX_EYE_PLANES = 8;
uniform vec4 eye_planes[MAX_EYE_PLANES];
uniform int eye_plane_weights[MAX_EYE_PLANES];
uniform int eye_plane_count;
#endif

int count_at_eye(int i, vec3 dir) {
  int count = eye_counts[LIGHT_DATA(i)];
#ifdef EYE_PLANES
  for (int k = 0; k < eye_plane_count; ++k)
    if (int(eye_planes[k].w) == LIGHT_DATA(i) && dot(eye_planes[k].xyz, dir) > 0.0) count += eye_plane_weights[k];
#endif
  return count;
}


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
    if (crossing_light(nodes[3u * node + 1u]) == LIGHT_DATA(i)) break;
  return node;
}

// The lit intervals of a pixel's ray, in order over all its lights: `index`
// counts them, the first `skip` were summed by an earlier pass (LOOP_LIMIT).
struct Walk {
  vec3 sum;
  uint index, skip;
  bool stopped;  // llvmpipe's loop limit was reached: the rest waits for another pass
};

#ifdef LOOP_LIMIT
// llvmpipe ends an invocation's loops once their iterations, summed over all of
// them (over its SIMD batch of 8 pixels), reach LOOP_LIMIT (docs/decisions.md,
// Numerics): pixels with many lit intervals, each with its correction's samples
// and Γ's panels, lost the end of their sum, silently, and no count known in
// advance bounds the work well. So each interval is checked after it is summed:
// once the limit is spent every loop ends after one iteration, and a loop of
// two ends after one. The interval that met the limit is dropped, and the pixel
// goes on from it in another pass (the host runs passes while any pixel is
// unfinished). A pixel that fits no interval in a pass may owe it to its
// batch (another pixel's interval spent the limit they share): it tries
// again, and every fourth such pass halves its samples; with none left to
// halve it gives up, counted.
layout(r32ui, binding = 2) uniform uimage2D progress;  // intervals done | passes without one << 24, or FINISHED
uniform int resume;  // 0 in the first pass
const uint FINISHED = 0xffffffffu;

bool loop_limit_reached() {
  int iterations = 0;
  for (int k = 0; k < 2 + int(frame.size.x < 0.0); ++k) ++iterations;  // a bound the compiler can't fold
  return iterations < 2;
}
#endif

void add_interval(int i, vec3 dir, float a, float b, inout Walk w) {
  if (w.stopped || w.index++ < w.skip) return;  // summed by an earlier pass
  vec3 gamma = lit_gamma(i, frame.eye, dir, a, b);
#ifdef LOOP_LIMIT
  if (loop_limit_reached()) {
    w.stopped = true;
    --w.index;
    return;
  }
#endif
  w.sum += gamma;
}

// Light i along [0, d]: Γ over the stretches where its count is 0 or less.
// Counts are never below 0 in exact arithmetic (shadow volumes contain a
// point a non-negative number of times; the lit pyramids of a beam tree do
// not overlap); where pyramids overlap by their ε-thick planes, a point is in
// two and the count reads −1, which is lit all the same.
void light_airlight(int i, uint head, vec3 dir, float d, inout Walk w) {
  int count = count_at_eye(i, dir);
  float start = 0.0;  // where the current lit stretch began (when count <= 0)
  // The events, then the ray's end as one more that closes a lit stretch: one
  // add_interval per light, so one copy of Γ (lit_gamma.glsl: each copy costs
  // seconds of llvmpipe's compile).
  uint node = next_event(i, head);
  for (bool more = true; more && !w.stopped;) {
    more = node != END_OF_LIST;
    float t = d;
    int after = 1;
    if (more) {
      t = node_t(node);
      after = count + crossing_change(nodes[3u * node + 1u]);
      node = next_event(i, node_next(node));
    }
#ifdef LOOP_LIMIT
    // The walk itself cut short: this light's later events unread, its last
    // stretch unknown (and add_interval probes only intervals it sums).
    if (!more && loop_limit_reached()) {
      w.stopped = true;
      return;
    }
#endif
    if (count <= 0 && after > 0) add_interval(i, dir, start, t, w);
    if (count > 0 && after <= 0) start = t;
    count = after;
  }
#ifdef LOOP_LIMIT
  // The limit ends the walk's loop itself, before its last turn.
  if (!w.stopped && loop_limit_reached()) w.stopped = true;
#endif
}

void main() {
  FRAME_PIXEL_OR_RETURN(pixel);
  Walk w = Walk(vec3(0.0), 0u, 0u, false);
  uint list = imageLoad(heads, pixel).r;
#ifdef LOOP_LIMIT
  uint state = resume == 0 ? 0u : imageLoad(progress, pixel).r, misses = state >> 24;
  if (state == FINISHED) return;
  w.skip = state & 0xffffffu;
  correction_samples = SAMPLES >> (misses / 4u);
  if (resume == 0) {
    list = sorted(list);
    imageStore(heads, pixel, uvec4(list));
    if (loop_limit_reached()) {  // the sort itself was cut short: its list may have lost nodes
      imageStore(airlight_out, pixel, vec4(0.0, 0.0, 0.0, 1.0));
      imageStore(progress, pixel, uvec4(FINISHED));
      atomicAdd(loop_limited, 1u);
      return;
    }
  }
#else
  list = sorted(list);
#endif
  PixelRay ray = load_pixel_ray(pixel);
  cut_into_pieces(ray.dir, ray.d);
#define ADD_LIGHT(i) light_airlight(i, list, ray.dir, ray.d, w);
  FOR_EACH_LIGHT_SHARED(ADD_LIGHT)
#undef ADD_LIGHT
#ifdef LOOP_LIMIT
  vec3 earlier = resume == 0 ? vec3(0.0) : imageLoad(airlight_out, pixel).rgb;  // earlier passes' sum
  imageStore(airlight_out, pixel, vec4(earlier + w.sum, 1.0));
  uint next = FINISHED;
  if (w.stopped && w.index > w.skip) next = w.index | (misses << 24);  // on from the interval that met the limit
  else if (w.stopped && (SAMPLES >> ((misses + 1u) / 4u)) > 0) next = w.skip | ((misses + 1u) << 24);
  else if (w.stopped) atomicAdd(loop_limited, 1u);  // given up: the rest of the sum is missing
  if (next != FINISHED) atomicAdd(unfinished, 1u);
  imageStore(progress, pixel, uvec4(next));
#else
  imageStore(airlight_out, pixel, vec4(w.sum, 1.0));
#endif
}
