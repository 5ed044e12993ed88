// The march shared by raymarch and interleaved (Tóth 2009 §3.1–4.1, Kingston
// 4.1): Σ_k w_k·Σ_lights V·inscatter at samples x_k along a view ray, over a
// subset of the N sample indices (all of them for raymarch; k ≡ q mod M² for
// interleaved's pixel q).
//
// Marched in view (world) space, as Kingston's raymarchViewSpaceAirlight: the
// lights of one march share its sample positions and the eye's optical depth;
// Tóth's light space only saves the subtraction x − light.
//
// Sample k of N sits at u = (k + offset)/N of its interval: offset 0.5 puts it
// at the middle of its step (Tóth's eq. 1 sums N + 1 end-point terms, error
// ~1/N; the midpoint rule's is ~1/N², docs/decisions.md), a per-pixel noise offset
// (Kingston §5.1.1) turns the steps' banding into noise. u maps to the ray by
//  - uniform steps (the documents' method): x = a + u·(b − a), w = (b − a)/N;
//  - equiangular steps (Kulla & Fajardo 2012, "Importance sampling techniques
//    for path tracing in participating media", §3, here deterministic): u is
//    uniform in the angle θ seen from the light's foot point on the ray, at
//    distance h: x = foot + h·tan θ, w = dθ·h/cos²θ. Since r² = h²/cos²θ, the
//    integrand in θ is I/h times smooth factors: the 1/r² peak of a ray passing
//    near a point or spot light, narrower than a uniform step, is integrated
//    exactly. Each such light needs its own foot point, hence its own march;
//    directional lights (no 1/r²) keep uniform steps.
#include "methods/kit/frame/scene.glsl"
#include "methods/kit/sampling/equiangular.glsl"

#define SAMPLING_UNIFORM 0      // the `sampling` setting's choices, in order (kit::Sampling)
#define SAMPLING_EQUIANGULAR 1

// Which of the N sample indices an invocation evaluates: k = first, first +
// stride, … below end.
struct SampleRange {
  int count;  // N
  int first;
  int stride;
  int end;
};

// ---- marching -----------------------------------------------------------------
// Loops over lights are unrolled by FOR_EACH_LIGHT (SceneFrame::defines), the
// per-light marches once per light structure (FOR_EACH_LIGHT_SHARED), so each
// light's index — and with it its type, shadow kind, gobo and beam — is a
// constant in its copy of the code, and `group` is a constant at every call:
// a sample pays only for the lights it evaluates, as they are.

#ifndef SAMPLING
#define SAMPLING SAMPLING_UNIFORM
#endif

const int ALL_LIGHTS = -1;      // `group` of march_segment: every light,
const int UNBOUNDED_SUNS = -2;  // the directional lights without a beam, or one light (>= 0)

bool unbounded_sun(int i) { return light_types[i] == LIGHT_DIRECTIONAL && !has_beam(i); }

bool in_group(int i, int group) {
  return group == ALL_LIGHTS || (group == UNBOUNDED_SUNS ? unbounded_sun(i) : i == group);
}

// Whether every sample of the march of `group` lies in light i's cone: the
// light's own march, over its lit interval.
bool in_own_cone(int i, int group) { return i == group && lit_interval_in_cone(i); }

bool any_unbounded_sun() {
  bool any = false;
#define OR_UNBOUNDED_SUN(i) any = any || unbounded_sun(i);
  FOR_EACH_LIGHT(OR_UNBOUNDED_SUN)
#undef OR_UNBOUNDED_SUN
  return any;
}

#ifdef SPREAD
// Σ over the marches of Σ_k (y_k − y_{k−1})², y_k = w_k·Σ V·inscatter the
// terms of successive samples of one march: the variance estimator of
// systematic sampling (successive differences measure how rough the integrand
// is between the samples, not how much it varies along the ray). Interleaved's
// guard turns it into the standard error of a pixel's own estimate.
vec3 march_spread = vec3(0.0);
#endif

// ---- where the steps go --------------------------------------------------------
// Equiangular steps weighted by the scattering (not in the documents): inside
// a bounded volume σs may be many times the filling medium's (biri_media: 12×),
// so the integrand jumps at the chord's ends and a short chord gets a few of the
// N samples. Interleaved's pixels each take one residue of the indices
// (Tóth §4.1), and where neighbouring rays cross a volume at other indices the
// window adds some samples of a chord twice and misses others: a bias per
// residue, seen as banding and as bright volume outlines. So the angle θ seen
// from the light is spent in proportion to σ̄(x)·dθ, σ̄ the mean over channels
// of σs on each piece of the ray (cut_into_pieces): sample k of N sits at the
// same fraction of ∫σ̄/r² on every ray, as the light guide (light_guide_of)
// measures it, and a chord gets its share of samples on every ray that crosses it.
//
// Even steps (directional lights, beams) are spent in proportion to
// σ̄(x)·exp(−k·t)·dt, k the least over channels of σt (so no channel's
// transmittance to the eye falls slower than the steps assume): in a dense
// volume or medium the integrand falls by the eye's transmittance, and even
// steps left most of a chord of optical depth 15 with nothing to measure
// (random scenes 49 and 51: rRMSE 0.37 and 0.15 at 64 steps); k is scaled
// down so that the density falls by e^MAX_STEP_DEPTH at most over the
// segment (weigh_pieces). Inside a piece the exponential is inverted in
// closed form. `sampling=uniform` keeps the documents' plain steps.
float piece_start[PIECES + 1];  // θ (equiangular) or t (even) at each piece's ends
float piece_mass[PIECES + 1];   // Σ of the pieces' shares before
float piece_density[PIECES];    // at each piece's start: σ̄, times exp(−depth) for even steps
float piece_decay[PIECES];      // k on each piece (even steps), 0 for equiangular
bool weighted = false;          // whether step_sample spends the steps by the pieces
const float MAX_STEP_DEPTH = 3.0;

float channel_mean(vec3 c) { return (c.r + c.g + c.b) / 3.0; }

// The slowest fall of the eye's transmittance per metre at x, over channels: 0
// under the simplified model (eye_leg_depth).
float least_sigma_t_at(vec3 x) {
  if (simplified_model()) return 0.0;
  vec3 sigma = sigma_t_at(x);
  return min(sigma.r, min(sigma.g, sigma.b));
}

// ∫ exp(−k·t) dt over [a, b] per channel, k ≥ 0: the length where k = 0.
vec3 transmitted_length(vec3 k, float a, float b) {
  vec3 x = k * (b - a);
  vec3 fraction = mix((vec3(1.0) - exp(-x)) / max(x, vec3(1e-30)), vec3(1.0) - 0.5 * x, lessThan(x, vec3(1e-3)));
  return exp(-k * a) * (b - a) * fraction;
}

// The y where ∫ exp(−k·y') dy' over [0, y] reaches f (k ≥ 0): transmitted_length's inverse.
float decayed_inverse(float k, float f) {
  float x = k * f;
  return x < 1e-3 ? f * (1.0 + 0.5 * x) : -log(max(1.0 - x, 1e-30)) / k;
}

// The pieces of segment s (a march's interval) and their shares: equiangular
// weighted by σ̄ only where volumes make σ̄ vary.
void weigh_pieces(vec3 dir, Segment s) {
  bool even = s.even;
  weighted = SAMPLING != SAMPLING_UNIFORM && (even || VOLUME_COUNT > 0);
  if (!weighted) return;
  piece_start[0] = even ? s.a : s.theta_a;
  piece_mass[0] = 0.0;
  float depth = 0.0;  // the eye's least optical depth over the segment, by the steps' k
  for (int p = 0; p < PIECES; ++p) {
    float a = clamp(breaks[p], s.a, s.b), b = clamp(breaks[p + 1], s.a, s.b);
    piece_start[p + 1] = p + 1 == PIECES ? (even ? s.b : s.theta_b) : (even ? b : atan2_accurate(b - s.foot, s.h));
    vec3 x = frame.eye + 0.5 * (a + b) * dir;
    piece_decay[p] = even ? least_sigma_t_at(x) : 0.0;
    piece_density[p] = channel_mean(sigma_s_at(x));
    depth += piece_decay[p] * max(piece_start[p + 1] - piece_start[p], 0.0);
  }
  // The steps' density falls by e^MAX_STEP_DEPTH at most along the segment:
  // the transmittance is not the whole integrand, and where the eye stands in
  // a shadow whose depth is 8, steps spent by it left the lit part beyond with
  // none (random scene 13, its sun alone: rRMSE 0.092 → 1.15 uncapped).
  float scale = min(1.0, MAX_STEP_DEPTH / max(depth, 1e-30));
  depth = 0.0;
  for (int p = 0; p < PIECES; ++p) {
    float width = max(piece_start[p + 1] - piece_start[p], 0.0);
    piece_decay[p] *= scale;
    piece_density[p] *= exp(-depth);
    piece_mass[p + 1] = piece_mass[p] + piece_density[p] * transmitted_length(vec3(piece_decay[p]), 0.0, width).x;
    depth += piece_decay[p] * width;
  }
}

// segment_sample with the steps spent by the pieces' shares: u ∈ (0, 1) of n at
// the fraction u of the mass; plain steps where nothing scatters.
vec2 step_sample(Segment s, float u, int n) {
  float mass = piece_mass[PIECES];
  if (!weighted || !(mass > 0.0)) return segment_sample(s, u, n);
  float target = u * mass;
  // The piece that holds the target, by selects over the unrolled pieces: no
  // array indexed by a variable, which Mesa lowers to if-ladders (slow to
  // compile and to run on llvmpipe).
  float start = piece_start[0], width = 0.0, before = 0.0, density = 1.0, k = 0.0;
  for (int p = 0; p < PIECES; ++p)
    if (piece_mass[p + 1] > piece_mass[p] && piece_mass[p] <= target) {
      start = piece_start[p];
      width = piece_start[p + 1] - piece_start[p];
      before = piece_mass[p];
      density = piece_density[p];
      k = piece_decay[p];
    }
  float y = min(decayed_inverse(k, (target - before) / density), width);
  // dy per unit of u·n; the floor keeps a share that underflowed finite (its integrand is as small)
  float step = mass / (float(n) * max(density * exp(-k * y), 1e-30 * mass));
  if (s.even) return vec2(start + y, step);
  float z = s.h * tan(start + y);
  return vec2(s.foot + z, step * (s.h + z * z / s.h));  // dx = h/cos²θ·dθ
}

// Σ over the range's samples k of w_k·Σ_{lights i in group} V_i·inscatter_i(x_k)
// (Tóth eq. 1, Kingston eq. 26) on segment s of the ray eye + t·dir.
vec3 march_segment(vec3 dir, Segment s, SampleRange r, float offset, int group) {
  if (!(s.b > s.a)) return vec3(0.0);
  vec3 eye = frame.eye;
  vec3 sum = vec3(0.0);
#ifdef SPREAD
  vec3 previous = vec3(0.0);
  bool first = true;
#endif
  // Equiangular steps not spent by the pieces walk in θ (equiangular_walk);
  // `walk` is a constant at every call, so the other path folds away.
  bool walk = !s.even && !weighted;
  EquiangularWalk w = equiangular_walk(s, (float(r.first) + offset) / float(r.count),
                                       float(r.stride) / float(r.count), r.count);
  // Runtime bounds: the steps and this pixel's share of them are settings and
  // pixel positions, not the scene's structure.
  for (int k = r.first; k < r.end; k += r.stride) {
    vec2 t = walk ? walk_sample(s, w) : step_sample(s, (float(k) + offset) / float(r.count), r.count);
    if (walk) step_walk(w);
    vec3 x = eye + t.x * dir;
    vec3 eye_depth = eye_leg_depth(eye, x);
    vec3 e = vec3(0.0);
#define ADD_LIGHT_SAMPLE(i)                                             \
    if (in_group(i, group)) {                                           \
      vec3 c = inscatter(i, x, dir, eye_depth, in_own_cone(i, group));  \
      if (c != vec3(0.0)) e += c * shadow_visibility(i, x);             \
    }
    FOR_EACH_LIGHT(ADD_LIGHT_SAMPLE)
#undef ADD_LIGHT_SAMPLE
    sum += e * t.y;
#ifdef SPREAD
    vec3 difference = first ? vec3(0.0) : e * t.y - previous;
    march_spread += difference * difference;
    previous = e * t.y;
    first = false;
#endif
  }
  return sum;
}

// Where light i's march over its lit interval `lit` puts its steps: equiangular
// about a point or spot light (weighted by the scattering), else even.
Segment light_steps(int i, vec3 dir, vec2 lit) {
  bool even = SAMPLING == SAMPLING_UNIFORM || has_beam(i) || light_types[i] == LIGHT_DIRECTIONAL;
  Segment s = even ? uniform_segment(lit.x, lit.y)
                   : equiangular_segment(lit.x, lit.y, frame.eye, dir, LIGHT(i).position);
  weigh_pieces(dir, s);
  return s;
}

// Light i's own march over the part of [t0, t1] it lights: with equiangular
// sampling even in the angle seen from a point or spot light, else (and along
// a beam's box or a directional light) in even steps.
vec3 march_between(int i, vec3 dir, float t0, float t1, SampleRange r, float offset) {
  vec3 eye = frame.eye;
  vec2 lit = lit_interval(i, eye, dir, t0, t1);
  if (!(lit.y > lit.x)) return vec3(0.0);
  return march_segment(dir, light_steps(i, dir, lit), r, offset, i);
}

// Equiangular: light i's own march over the part of [0, d] it lights (the
// unbounded suns march together).
vec3 march_light(int i, vec3 dir, float d, SampleRange r, float offset) {
  return unbounded_sun(i) ? vec3(0.0) : march_between(i, dir, 0.0, d, r, offset);
}

// L_air along the unit view ray `dir` up to distance d, over the range's samples.
// Equiangular: one march per point or spot light over the part of [0, d] it
// lights, one uniform march per beam over its box, and one uniform march for
// the directional lights without a beam.
vec3 march_airlight(vec3 dir, float d, SampleRange r, float offset) {
#if SAMPLING == SAMPLING_UNIFORM
  return march_segment(dir, uniform_segment(0.0, d), r, offset, ALL_LIGHTS);
#else
  vec3 sum = vec3(0.0);
  if (any_unbounded_sun()) {
    Segment suns = uniform_segment(0.0, d);
    weigh_pieces(dir, suns);
    sum += march_segment(dir, suns, r, offset, UNBOUNDED_SUNS);
  }
#define ADD_LIGHT_MARCH(i) sum += march_light(i, dir, d, r, offset);
  FOR_EACH_LIGHT_SHARED(ADD_LIGHT_MARCH)
#undef ADD_LIGHT_MARCH
  return sum;
#endif
}

// ---- the guide of interleaved's normalized gather -------------------------------

// ∫ of segment s's sample density over [a, b] ⊂ [s.a, s.b]: ∫dx/r² = Δθ/h about
// the light's foot point (exact, as equiangular_segment), or the length.
float segment_measure(Segment s, float a, float b) {
  if (s.even) return b - a;
  return (atan2_accurate(b - s.foot, s.h) - atan2_accurate(a - s.foot, s.h)) / s.h;
}


// What a beam's light leg adds to a directional light's optical depth per metre
// along the view ray in the filling medium (light_leg_depth): σt·cos.
vec3 beam_decay(int i, vec3 dir) {
  return has_beam(i) ? frame.medium_sigma_t * dot(dir, LIGHT(i).direction) : vec3(0.0);
}

// Light i's guide on [a, b] inside the piece of the ray that starts at `start`,
// where the eye's optical depth is `depth` and σt is sigma_t (x its middle):
// ∫σs·p·T·dx/r² with T the eye's transmittance, to the light too for a point
// or spot light. A directional light: cos θ is the same all along the ray and
// T = exp(−depth − σt·(t − start) − leg(t)) in closed form, where a beam's light
// leg is exact at a and grows by beam_decay past it; the leg at a must be
// there, not only its growth, or the beam's guide is off by a constant beside a
// point light's and the gather mixes the two wrongly (random scene 97). A point
// or spot light: with t − foot = h·tan u, dx/r² = du/h and cos θ = −sin u
// (the light's travel against the view ray, as inscatter_unmapped), so the
// integral is 4-point Gauss–Legendre in u, T at each node.
vec3 guide_piece(int i, Segment s, vec3 dir, vec3 x, float start, vec3 depth, vec3 sigma_t, float a, float b) {
  if (light_types[i] == LIGHT_DIRECTIONAL) {
    vec3 leg = has_beam(i) ? light_leg_depth(i, frame.eye + a * dir) : vec3(0.0);
    vec3 k = sigma_t + beam_decay(i, dir);
    return scattering(x, dot(-LIGHT(i).direction, dir)) * exp(-depth - sigma_t * (a - start) - leg) *
           transmitted_length(k, 0.0, b - a);
  }
  const vec4 node = vec4(-0.8611363116, -0.3399810436, 0.3399810436, 0.8611363116);
  const vec4 weight = vec4(0.3478548451, 0.6521451549, 0.6521451549, 0.3478548451);
  float u_a = atan2_accurate(a - s.foot, s.h), u_b = atan2_accurate(b - s.foot, s.h);  // h > 0 (equiangular_segment)
  vec3 sum = vec3(0.0);
  for (int n = 0; n < 4; ++n) {
    float u = mix(u_a, u_b, 0.5 * (node[n] + 1.0));
    float t = s.foot + s.h * tan(u);
    vec3 at = frame.eye + t * dir;
    sum += weight[n] * scattering(x, -sin(u)) * exp(-depth - sigma_t * (t - start) - light_leg_depth(i, at));
  }
  return sum * (0.5 * (u_b - u_a) / s.h);
}

// Per channel, Σ over lights of I·∫σs(x)·p(x)·T(x)·dx/r² over the part of
// [0, d] each lights (r² = 1 and I the irradiance for a directional light), σs·p
// the filling medium's plus that of each volume the ray crosses there
// (docs/design.md §1), summed over the ray's pieces (cut_into_pieces), and T as
// guide_piece: L_air without V, gobo and smooth edge, and without a directional
// light's leg through volumes. It carries what changes fastest from pixel to
// pixel — the 1/h peak next to a light, a cone's edge, the length of the ray, a
// volume's outline and chord and the light it lets through to the eye, the
// phase's peak across the image — and is 0 where no light reaches. Random
// scenes 35, 36 and 38 (a beam seen along its travel, Schlick g = −0.58 to
// −0.87, optical depth about 1) and 8 (a point light at the image's centre, HG
// g = −0.78) failed at 32×24 when it left out the phase and the transmittance;
// 49 (a sun on a volume of optical depth 15) when it left out the volumes'.
vec3 light_guide_of(int i, vec3 dir, float d) {
  vec3 eye = frame.eye;
  vec2 lit = lit_interval(i, eye, dir, 0.0, d);
  if (!(lit.y > lit.x)) return vec3(0.0);
  bool sun = light_types[i] == LIGHT_DIRECTIONAL;
  Segment s = sun ? uniform_segment(lit.x, lit.y) : equiangular_segment(lit.x, lit.y, eye, dir, LIGHT(i).position);
  if (simplified_model())  // the filling medium alone, isotropic (scattering)
    return LIGHT(i).color * frame.medium_sigma_s * segment_measure(s, lit.x, lit.y);
  vec3 guide = vec3(0.0), depth = vec3(0.0);
  for (int p = 0; p < PIECES; ++p) {
    float start = breaks[p], end = breaks[p + 1];
    vec3 x = eye + 0.5 * (start + end) * dir;
    vec3 sigma_t = sigma_t_at(x);
    float a = max(start, lit.x), b = min(end, lit.y);
    if (b > a) guide += guide_piece(i, s, dir, x, start, depth, sigma_t, a, b);
    depth += sigma_t * (end - start);
  }
  return LIGHT(i).color * guide;
}

// One copy per light structure (FOR_EACH_LIGHT_SHARED), not per light: each
// copy is paid in llvmpipe's compile of the first frame.
vec3 light_guide(vec3 dir, float d) {
  vec3 guide = vec3(0.0);
#define ADD_LIGHT_GUIDE(i) guide += light_guide_of(i, dir, d);
  FOR_EACH_LIGHT_SHARED(ADD_LIGHT_GUIDE)
#undef ADD_LIGHT_GUIDE
  return guide;
}

// The volume key of interleaved's gather (not in Tóth): the share of the guide
// (light_guide_of) that the lights reach past V and light map, from KEY_POINTS
// points per light at the march's own quantiles (step_sample) — what the
// guide leaves out and the gather must share between rays. Where the rays of a
// window cross a volume's lit part differently — a volume in a shadow beside
// haze that is lit, a shadow plane seen edge-on inside a volume — the key
// jumps, as the G-buffer distance does at a silhouette, and the gather leaves
// those neighbours out (gather.comp.glsl). It only decides which neighbours
// join, never the value, so a few points suffice. Without volumes it is 0.
#if VOLUME_COUNT > 0
const int KEY_POINTS = 8;
float volume_key(vec3 dir, float d) {
  float all_mass = 0.0, lit_mass = 0.0;
#define ADD_LIGHT_KEY(i)                                                                               \
  {                                                                                                    \
    vec2 lit = lit_interval(i, frame.eye, dir, 0.0, d);                                                \
    if (lit.y > lit.x) {                                                                               \
      Segment s = light_steps(i, dir, lit);                                                            \
      float mass = channel_mean(light_guide_of(i, dir, d)), seen = 0.0;                                \
      for (int k = 0; k < KEY_POINTS; ++k) {                                                           \
        vec3 x = frame.eye + step_sample(s, (float(k) + 0.5) / float(KEY_POINTS), KEY_POINTS).x * dir; \
        seen += channel_mean(light_map(i, x)) * shadow_visibility(i, x);                               \
      }                                                                                                \
      all_mass += mass;                                                                                \
      lit_mass += mass * seen / float(KEY_POINTS);                                                     \
    }                                                                                                  \
  }
  FOR_EACH_LIGHT(ADD_LIGHT_KEY)
#undef ADD_LIGHT_KEY
  return all_mass > 0.0 ? lit_mass / all_mass : 0.0;
}
#else
float volume_key(vec3 dir, float d) { return 0.0; }
#endif

// What the w of a partial sum says: the march (march.comp.glsl) writes it, the
// gather (methods/interleaved/gather.comp.glsl) reads it and writes its own
// passes' sums with the first two.
const float PARTIAL_EMPTY = 0.0;   // nothing to share: no light reaches the ray (normalized), no neighbour joined
const float PARTIAL_SHARED = 1.0;  // a partial sum for the gather to share
const float PARTIAL_OWN = 2.0;     // all N samples the pixel's own (guard): left out of every window

// A pixel's sum divided by its guide per channel (0 where the guide is), and in
// w whether any light reaches its ray (PARTIAL_SHARED) or not (PARTIAL_EMPTY).
vec4 guided(vec3 sum, vec3 guide) {
  bvec3 lit = greaterThan(guide, vec3(0.0));
  return vec4(mix(vec3(0.0), sum / max(guide, vec3(1e-30)), lit), any(lit) ? PARTIAL_SHARED : PARTIAL_EMPTY);
}
