// shadow_planes (Biri 2006 §4.2, §5.1): per pixel, L_air = Σ_lights Σ over the
// lit intervals [a, b] of the view ray of Γ(a → b), the closed-form airlight
// of the medium that fills space (closed_form.glsl, the twin of optics::gamma).
//
// The lit intervals come from counting: light i's shadow count starts at the
// eye's (how many triangle shadow volumes contain the eye, counted on the CPU
// per frame) and changes by each crossing's signed weight in the order of t;
// the ray is lit by i where the count is 0. Counting is exact whatever the
// order or nesting of the volumes — shadow in shadow, the eye inside one or
// several volumes — which Biri gets from drawing back to front with the
// stencil; here each light walks the pixel's crossings in the order of t
// (next_event). Crossings at equal t give empty intervals, whose Γ is 0.
//
// Gobos: Γ has no closed form with a light map's colours, so each lit
// interval's Γ is multiplied by the gobo's colour averaged over GOBO_SAMPLES
// (a setting) points of the interval, weighted as Γ weighs them
// (interval_gobo), docs/decisions.md.
#define SCENE_IN_REGISTERS
#include "methods/kit/closed_form.glsl"
#include "methods/kit/equiangular.glsl"
#include "methods/shadow_planes/crossings.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) writeonly uniform image2D airlight_out;
layout(r32ui, binding = 1) readonly uniform uimage2D heads;

uniform int eye_counts[LIGHT_COUNT];  // each light's shadow count at the eye


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

// light_map without the gobo: the spot's cone factor, or 1 inside a beam.
float light_shape(int i, vec3 x) {
  if (light_types[i] != LIGHT_SPOT) return has_beam(i) && !inside_beam(light_beam(i), x) ? 0.0 : 1.0;
  vec3 delta = x - LIGHT(i).position;
  float r = length(delta);
  return spot_cone(LIGHT(i).direction, LIGHT(i).cone, light_edges[i] ? LIGHT(i).edge : 0.0,
                   r > 0.0 ? delta / r : LIGHT(i).direction);
}

// The gobo's colour over light i's lit interval [a, b] as Γ weighs it: at
// GOBO_SAMPLES points where the light reaches (lit_interval: the spot's cone,
// the beam's box), even in the angle seen from a spot (uniform along a beam),
// Σ f·map / Σ f·shape with f the unoccluded in-scattering without the light
// map times the sample's weight: a ratio estimator that is exact when the
// gobo is constant over the interval and keeps the correlation of its colour
// with the cone's edge, the phase function and extinction (docs/decisions.md).
vec3 interval_gobo(int i, vec3 eye, vec3 dir, float a, float b) {
  if (!light_gobos[i]) return vec3(1.0);
  vec2 lit = lit_interval(i, eye, dir, a, b);
  if (!(lit.y > lit.x)) return vec3(1.0);  // Γ is 0 there
  Segment s = light_types[i] == LIGHT_SPOT ? equiangular_segment(lit.x, lit.y, eye, dir, LIGHT(i).position)
                                           : uniform_segment(lit.x, lit.y);
  vec3 mapped = vec3(0.0), shaped = vec3(0.0);
  for (int k = 0; k < GOBO_SAMPLES; ++k) {
    vec2 t = segment_sample(s, (float(k) + 0.5) / float(GOBO_SAMPLES), GOBO_SAMPLES);
    vec3 x = eye + t.x * dir;
    vec3 f = inscatter_unmapped(i, x, dir, eye_leg_depth(eye, x)) * t.y;
    mapped += f * light_map(i, x);
    shaped += f * light_shape(i, x);
  }
  return mix(vec3(1.0), mapped / max(shaped, vec3(1e-30)), greaterThan(shaped, vec3(0.0)));
}

vec3 lit_gamma(int i, vec3 eye, vec3 dir, float a, float b) {
  if (!(b > a)) return vec3(0.0);
  return closed_form_airlight(i, eye, dir, a, b) * interval_gobo(i, eye, dir, a, b);
}

// Light i along [0, d]: Γ over the stretches where its count is 0.
vec3 light_airlight(int i, uint head, vec3 dir, float d) {
  vec3 eye = frame.eye;
  int count = eye_counts[i];
  float start = 0.0;  // where the current lit stretch began (when count == 0)
  float t = -1.0;     // the last event: before every crossing (all have t > 0)
  vec3 sum = vec3(0.0);
  // Runtime bounds: the crossings along this ray.
  for (uint node = next_event(i, head, t, 0u); node != END_OF_LIST; node = next_event(i, head, t, node)) {
    t = node_t(node);
    int after = count + crossing_change(nodes[3u * node + 1u]);
    if (count == 0 && after != 0) sum += lit_gamma(i, eye, dir, start, t);
    if (count != 0 && after == 0) start = t;
    count = after;
  }
  if (count == 0) sum += lit_gamma(i, eye, dir, start, d);
  return sum;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, frame_size()))) return;
  load_scene();
  vec3 dir = pixel_ray(vec2(pixel) + 0.5);
  float d = surface_distance(pixel);
  uint list = imageLoad(heads, pixel).r;
  vec3 sum = vec3(0.0);
#define ADD_LIGHT(i) sum += light_airlight(i, list, dir, d);
  FOR_EACH_LIGHT(ADD_LIGHT)
#undef ADD_LIGHT
  imageStore(airlight_out, pixel, vec4(sum, 1.0));
}
