// Γ over one lit interval [a, b] of light i along a view ray (Biri 2006
// §4.2, Nilsson 2008 §3.2, Kingston's exact parts outside [front, back]): the
// closed-form airlight (closed_form.glsl, the twin of optics::gamma), cut into
// pieces inside fixed sets of media where bounded volumes lie across the ray
// (Biri §5.2), and corrected where Γ has no closed form. Shared by the
// lit-interval pass (lit_intervals.comp.glsl) and sv_march.
//
// Gobos and bounded volumes: Γ is closed only in one medium per leg and
// without a light map's colours; the ray is cut into pieces inside fixed sets
// of media (corrected_airlight), and each piece's Γ is multiplied by a ratio
// estimated at points of the piece, SAMPLES (a setting) per lit interval
// shared among its pieces (interval_correction, correction_samples),
// docs/decisions.md. A shader calls cut_into_pieces (scene.glsl) once per
// pixel before lit_gamma.
#include "methods/kit/gamma/closed_form.glsl"
#include "methods/kit/sampling/equiangular.glsl"

// Points per lit interval for interval_correction: SAMPLES, unless a pixel
// cannot fit one interval within llvmpipe's loop limit (lit_intervals.comp.glsl).
int correction_samples = SAMPLES;

// light_map without the gobo: the spot's cone factor, or 1 inside a beam.
float light_shape(int i, vec3 x) {
  if (light_types[i] != LIGHT_SPOT) return has_beam(i) && !inside_beam(light_beam(i), x) ? 0.0 : 1.0;
  vec3 delta = x - LIGHT(i).position;
  float r = length(delta);
  return spot_cone(LIGHT(i).direction, LIGHT(i).cone, light_edges[i] ? LIGHT(i).edge : 0.0,
                   r > 0.0 ? delta / r : LIGHT(i).direction);
}

// The optical depth of x's leg to light i as Γ takes it (unoccluded_airlight):
// σt at x all the way to a point or spot light, or back to a beam's aperture;
// none for an unbounded sun (closed_form.glsl).
vec3 gamma_light_depth(int i, vec3 x) {
  if (simplified_model()) return vec3(0.0);
  if (light_types[i] != LIGHT_DIRECTIONAL) return sigma_t_at(x) * length(LIGHT(i).position - x);
  return has_beam(i) ? sigma_t_at(x) * max(beam_depth(light_beam(i), x), 0.0) : vec3(0.0);
}

// What Γ leaves out over [a, b] of light i's lit interval, as a factor: a gobo's
// colours (no closed form) and, with bounded volumes, the light's leg through
// media other than those at the point (Γ is closed only for one medium per
// leg). At `samples` points where the light reaches (lit_interval: the spot's
// cone, the beam's box), even in the angle seen from a point or spot (uniform
// along a beam), the ratio Σ f·map / Σ f·shape·e^{τ − τ_Γ} of the exact
// in-scattering without the light map f (scene.glsl, every medium on both
// legs) times the light map (cone × gobo), over what Γ integrates (the cone
// alone, the light's leg τ_Γ by gamma_light_depth instead of τ): exact when
// that ratio is constant over the interval, and it keeps the gobo's
// correlation with the cone's edge, the phase and extinction
// (docs/decisions.md). 1 without a gobo or a volume: Γ is then exact.
vec3 interval_correction(int i, vec3 eye, vec3 dir, float a, float b, int samples) {
#if !HAS_GOBO && VOLUME_COUNT == 0
  return vec3(1.0);  // left out before it is inlined (scene.glsl)
#else
  if (!light_gobos[i] && VOLUME_COUNT == 0) return vec3(1.0);
  vec2 lit = lit_interval(i, eye, dir, a, b);
  if (!(lit.y > lit.x)) return vec3(1.0);  // Γ is 0 there
  Segment s = light_types[i] == LIGHT_DIRECTIONAL ? uniform_segment(lit.x, lit.y)
                                                  : equiangular_segment(lit.x, lit.y, eye, dir, LIGHT(i).position);
  vec3 exact = vec3(0.0), modelled = vec3(0.0);
  for (int k = 0; k < samples; ++k) {
    vec2 t = segment_sample(s, (float(k) + 0.5) / float(samples), samples);
    vec3 x = eye + t.x * dir;
    vec3 f = inscatter_unmapped(i, x, dir, eye_leg_depth(eye, x)) * t.y;
    exact += f * light_map(i, x);
    modelled += f * light_shape(i, x) * exp(light_leg_depth(i, x) - gamma_light_depth(i, x));
  }
  return mix(vec3(1.0), exact / max(modelled, vec3(1e-30)), greaterThan(modelled, vec3(0.0)));
#endif
}

// Γ over [a, b] in the medium that fills space, corrected for a gobo.
vec3 filling_airlight(int i, vec3 eye, vec3 dir, float a, float b) {
  return closed_form_airlight(i, eye, dir, a, b) * interval_correction(i, eye, dir, a, b, correction_samples);
}

#if VOLUME_COUNT > 0
// Γ over [a, b] piece by piece: per piece, the eye leg's exact transmittance
// to its start times Σ over its media (the one that fills space and each
// volume it lies in) of Γ with that medium's σs and phase and the piece's σt
// on both legs. Exact on the eye's leg and for the in-scattering; the light's
// leg is taken through the piece's media all the way to the light, which
// interval_correction corrects where it crosses other volumes — piece by
// piece: Γ's error differs by orders of magnitude between a piece inside a
// dense volume and one outside it, and one ratio over the whole interval
// weighed them by a few samples (random scene 41, a point light beside a
// volume of optical depth 7: rRMSE 4.1 at samples = 64 and 0.53 at 1024 with
// one ratio, 0.0005 at 64 per piece).
//
// The pieces are walked by a loop the compiler cannot unroll (from the first
// piece that overlaps [a, b] to the last): unrolled, each of the PIECES copies
// held 1 + VOLUME_COUNT closed forms and a correction loop, and a shader with a
// few lights and volumes took minutes to compile on llvmpipe.
vec3 corrected_airlight(int i, vec3 eye, vec3 dir, float a, float b) {
  // Under the simplified model the volumes neither scatter nor extinguish
  // (scattering, eye_leg_depth): their σs taken piece by piece made random
  // scene 232 427 times too bright.
  if (simplified_model()) return filling_airlight(i, eye, dir, a, b);
  int first = PIECES, last = -1;
  for (int p = 0; p < PIECES; ++p)
    if (min(b, breaks[p + 1]) > max(a, breaks[p])) {
      first = min(first, p);
      last = p;
    }
  int samples = max(correction_samples / max(last - first + 1, 1), 1);
  vec3 sum = vec3(0.0);
  for (int p = first; p <= last; ++p) {
    // breaks[p] by selects: indexed by p, Mesa would unroll the loop to the array's length
    float start = 0.0, end = 0.0;
    for (int q = 0; q < PIECES; ++q)
      if (q == p) {
        start = breaks[q];
        end = breaks[q + 1];
      }
    float t0 = max(a, start), t1 = min(b, end);
    if (!(t1 > t0)) continue;  // data: the piece misses this lit interval
    vec3 origin = eye + start * dir, middle = eye + 0.5 * (t0 + t1) * dir;
    vec3 sigma_t = sigma_t_at(middle);
    // The filling medium (n = 0) and the volumes that hold the piece, by one
    // component_airlight in a loop the compiler cannot unroll (spot_gamma).
    int held = 0;
#define COUNT_HOLDING(v) held += box_contains(middle, VOLUME(v).lo, VOLUME(v).hi) ? 1 : 0;
    FOR_EACH_VOLUME(COUNT_HOLDING)
#undef COUNT_HOLDING
    vec3 piece = vec3(0.0);
    for (int n = 0; n <= held; ++n) {
      MediumComponent m = MediumComponent(frame.medium_sigma_s, sigma_t, -1);
      int seen = 0;
#define TAKE_NTH_HOLDING(v)                                                    \
      if (box_contains(middle, VOLUME(v).lo, VOLUME(v).hi) && ++seen == n) \
        m = MediumComponent(VOLUME(v).sigma_s, sigma_t, v);
      FOR_EACH_VOLUME(TAKE_NTH_HOLDING)
#undef TAKE_NTH_HOLDING
      piece += component_airlight(i, m, origin, dir, t0 - start, t1 - start);
    }
    sum += exp(-eye_leg_depth(eye, origin)) * piece * interval_correction(i, eye, dir, t0, t1, samples);
  }
  return sum;
}
#else
vec3 corrected_airlight(int i, vec3 eye, vec3 dir, float a, float b) { return filling_airlight(i, eye, dir, a, b); }
#endif

vec3 lit_gamma(int i, vec3 eye, vec3 dir, float a, float b) {
  if (!(b > a)) return vec3(0.0);
  return corrected_airlight(i, eye, dir, a, b);
}
