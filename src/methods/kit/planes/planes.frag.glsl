// A fragment of virtual plane k at a pixel: its sample of the light's
// in-scattering, Dobashi eq. 5's I(θ,φ)·ξ·V, added into the float target by
// additive blending (no 8-bit quantization floor, unlike the paper's frame
// buffer). I(θ,φ) is the light map (light_map: spot cone and gobo, or the
// beam and its gobo), V the shadow-map test (Dobashi §5.2 in its modern form).
//
// The slab [k·dz, (k+1)·dz] is cut at the visible surface and to the light's
// lit interval: only that part counts, sampled at its middle (or at the
// pixel's jitter offset), so a surface inside a slab gets no step of up to dz
// in its fog and a shaft's edge no step across it.
//
// Specialized by PlanePass, one program per light structure and part:
// SHARED_LIGHT (the index of the structure's first light, whose constants the
// program takes; it draws light shared_light: scene.glsl),
// LATTICE_XI (ξ from the lattice), JITTER (per-pixel offsets of the samples
// within their slabs, Dobashi §7), LIT_SAMPLING (the slab's lit piece, else
// the slab as Dobashi); for a cut plane's pieces (plane_pass.cpp
// draw_pieces) FULL_SLABS (only slabs wholly in front of the surface),
// FULLY_LIT (no shadow test) or FULLY_LIT_GAMMA (Γ), and CUT_SLABS (a
// full-screen pass over the slabs the surface cuts).
#define SCENE_IN_REGISTERS
#include "methods/kit/frame/view_ray.glsl"
#include "methods/kit/gamma/closed_form.glsl"

layout(binding = BINDING_JITTER) uniform sampler2D jitter_offsets;  // R32F tile of values in [0, 1)

const int light = SHARED_LIGHT;
uniform float dz;

// A piece [ta, tb] of the ray eye + t·dir in the equiangular substitution of
// Kulla & Fajardo 2012, for the falloff f = 1/(a1 r² + a0) of a point or spot
// light (1/r² physical: a0 = 0, a1 = 1): with h the light's distance from the
// ray's line, s = t − foot, c = a0/a1 and h'² = h² + c, θ = atan(s/h') runs
// over [θa, θb] and ∫ f dt = Δθ/(a1 h'). Samples even in θ sit at even angles
// as seen from the light, where the cone's edge and the gobo change, and
// weigh ∫ f dt / f(r) each, exact for the falloff's peak of a piece passing
// within a slab's thickness of the light, which a sample at the middle of Δt
// misses. A constant falloff (a1 = 0) or no falloff (directional) keeps even
// steps in t (h = 0).
struct Piece {
  vec2 t;     // [ta, tb]
  float foot, h, c;
  vec2 theta;  // [θa, θb]
};

Piece even_piece(vec2 t) { return Piece(t, 0.0, 0.0, 0.0, vec2(0.0)); }

Piece angular_piece(vec3 light, vec3 eye, vec3 dir, vec2 t) {
  float a0 = simplified_model() ? frame.light_model_a0 : 0.0;
  float a1 = simplified_model() ? frame.light_model_a1 : 1.0;
  if (!(a1 > 0.0)) return even_piece(t);
  vec3 delta = light - eye;
  float foot = dot(delta, dir);
  vec3 side = delta - foot * dir;
  float c = a0 / a1;
  float h = max(sqrt(dot(side, side) + c), MIN_LIGHT_DISTANCE);
  return Piece(t, foot, h, c, vec2(atan2_accurate(t.x - foot, h), atan2_accurate(t.y - foot, h)));
}

// Samples for a piece of light i's lit interval: one per MAX_SAMPLE_ANGLE of
// Δθ for an angular piece (a spot's gobo dots span a few degrees), one per
// gobo texel the piece crosses in a beam, and at least one per
// MAX_SAMPLE_DEPTH of optical depth along it; at most MAX_PIECE_SAMPLES. Only
// a piece passing within about a slab's thickness of a light, crossing a
// patterned beam obliquely or inside a dense volume needs more than one: the
// extra samples cost nothing elsewhere. In a volume of optical depth 16 a slab
// held Δτ ≈ 5, and its one sample missed the transmittance's fall (random
// scenes 65 and 110: rRMSE 0.21 at 100 planes); at Δτ = 0.25 the midpoint
// rule's error on exp(−τ) is about Δτ²/24, 0.3 %.
const float MAX_SAMPLE_ANGLE = PI / 256.0;
const float MAX_SAMPLE_DEPTH = 0.25;
const int MAX_PIECE_SAMPLES = 64;
int piece_samples(int i, Piece p, vec3 dir) {
  float n = 1.0;
  if (p.h > 0.0) n = (p.theta.y - p.theta.x) / MAX_SAMPLE_ANGLE;
  else if (has_beam(i) && LIGHT(i).gobo_layer >= 0) {
    Beam b = light_beam(i);
    vec2 texels = vec2(gobo_size(i)) / b.size;  // per metre across the beam
    vec2 across = abs(vec2(dot(dir, b.right), dot(dir, b.up))) * (p.t.y - p.t.x);
    n = max(across.x * texels.x, across.y * texels.y);
  }
  if (!simplified_model()) {  // T = 1 there (eye_leg_depth)
    vec3 depth = sigma_t_at(frame.eye + 0.5 * (p.t.x + p.t.y) * dir) * (p.t.y - p.t.x);
    n = max(n, max(depth.r, max(depth.g, depth.b)) / MAX_SAMPLE_DEPTH);
  }
  return clamp(int(ceil(n)), 1, MAX_PIECE_SAMPLES);
}

// Sample u ∈ (0, 1) of n: where (x: t) and its weight (y: ∫ f dt / f(r) over
// its 1/n of the piece, or Δt/n for an even piece).
vec2 piece_sample(Piece p, vec3 light, vec3 eye, vec3 dir, float u, int n) {
  if (p.h == 0.0) return vec2(mix(p.t.x, p.t.y, u), (p.t.y - p.t.x) / float(n));
  float t = clamp(p.foot + p.h * tan(mix(p.theta.x, p.theta.y, u)), p.t.x, p.t.y);
  vec3 r = eye + t * dir - light;
  float r2 = max(dot(r, r) + p.c, MIN_LIGHT_DISTANCE * MIN_LIGHT_DISTANCE);
  return vec2(t, (p.theta.y - p.theta.x) / float(n) / p.h * r2);
}

#ifdef CUT_SLABS
uniform int plane_count;
#else
flat in int plane;
in vec3 xi;
#endif
layout(location = 0) out vec4 airlight;

// The light's in-scattering over the piece [t.x, t.y] of the pixel's ray,
// its samples at `offset` within their shares of it.
vec3 piece_airlight(vec3 dir, float cos_axis, vec2 t, float offset) {
  vec3 eye = frame.eye;
  vec3 light_position = LIGHT(light).position;
#if defined(LIT_SAMPLING) && !defined(LATTICE_XI)
  Piece p = light_types[light] != LIGHT_DIRECTIONAL ? angular_piece(light_position, eye, dir, t) : even_piece(t);
#else
  Piece p = even_piece(t);
#endif
#ifdef LIT_SAMPLING
  int n = piece_samples(light, p, dir);
#else
  int n = 1;
#endif
  vec3 sum = vec3(0.0);
  for (int k = 0; k < n; ++k) {
    vec2 s = piece_sample(p, light_position, eye, dir, (float(k) + offset) / float(n), n);
    vec3 x = eye + s.x * dir;
#ifdef LIT_SAMPLING
    vec3 map = light_map(light, x, lit_interval_in_cone(light));  // the piece lies in the lit interval
#else
    vec3 map = light_map(light, x);
#endif
#if defined(FULLY_LIT) || defined(FULLY_LIT_GAMMA)
    if (map == vec3(0.0)) continue;  // Nilsson §5.3: nothing shadows a fully lit part
#else
    if (map == vec3(0.0) || shadow_visibility(light, x) == 0.0) continue;
#endif
    // ξ per unit length along the ray (the lattice's is per unit depth) times
    // the sample's weight: Δt, or ∫ f dt / f(r), trading ξ's falloff for its integral.
#ifdef LATTICE_XI
    vec3 xi_here = xi * cos_axis;
#else
    vec3 xi_here = inscatter_unmapped(light, x, dir, eye_leg_depth(eye, x));
#endif
    sum += map * xi_here * s.y;
  }
  return sum;
}

// Plane k's sample over [z0, z1] of view depth along the pixel's ray.
vec3 slab_airlight(ivec2 pixel, vec3 dir, float cos_axis, float z0, float z1) {
  vec3 eye = frame.eye;
  // The slab's piece of the ray in front of the surface, cut to where the
  // light can arrive (a spot's cone, a beam's box): the sample never falls
  // outside a shaft that crosses the slab, so shafts keep their edges and thin
  // pieces (a ray grazing a spot's apex) their light.
#ifdef LIT_SAMPLING
  vec2 lit = lit_interval(light, eye, dir, z0 / cos_axis, z1 / cos_axis);
#else
  vec2 lit = vec2(z0, z1) / cos_axis;
#endif
  if (!(lit.y > lit.x)) return vec3(0.0);
#ifdef FULLY_LIT_GAMMA
  // Nilsson §5.4: no object lies between the slab and the light, so its
  // airlight is Γ over the piece — closed where the light has no gobo and no
  // volume bounds the medium, else sampled as below without the shadow test.
  if (!light_gobos[light] && VOLUME_COUNT == 0) return closed_form_airlight(light, eye, dir, lit.x, lit.y);
#endif
#ifdef JITTER
  float offset = texelFetch(jitter_offsets, pixel % textureSize(jitter_offsets, 0), 0).r;
#else
  float offset = 0.5;
#endif
#ifdef LIT_SAMPLING
  // Cut at the volumes' chord ends too: σs and σt jump there (Biri §5.2).
  cut_into_pieces(dir, lit.y);
  vec3 sum = vec3(0.0);
  for (int q = 0; q < PIECES; ++q) {
    vec2 piece = vec2(max(lit.x, breaks[q]), min(lit.y, breaks[q + 1]));
    if (piece.y > piece.x) sum += piece_airlight(dir, cos_axis, piece, offset);
  }
  return sum;
#else
  return piece_airlight(dir, cos_axis, lit, offset);
#endif
}

// An early exit writes zero, which the blending adds, where a discard would do:
// on llvmpipe a discard ahead of the slab's loops left wrong sums in the
// fragments that went on, once two volumes had phase sums (random scene 315:
// hybrid_clip 0.67 rRMSE where planes, the same shader without the early
// exit, was 1e-4; with the zero written, the two agree to the bit).
#define SKIP_FRAGMENT      \
  {                        \
    airlight = vec4(0.0);  \
    return;                \
  }

void main() {
  load_scene();
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 dir = pixel_ray(gl_FragCoord.xy);
  float cos_axis = dot(dir, frame.forward);
  float surface = surface_distance(pixel) * cos_axis;
  vec3 sum = vec3(0.0);
#ifdef CUT_SLABS
  // The slab the surface cuts, z0 < surface < z0 + dz, with z0 and z0 + dz as
  // its plane computes them. Rounding may make a neighbour's z0 fall below the
  // surface too: that one's piece is a rounding error of the depth, left out
  // (one evaluation per pixel, not three: llvmpipe runs every iteration).
  int k = clamp(int(ceil(surface / dz)) - 1, 0, plane_count - 1);
  if (float(k) * dz >= surface) k = max(k - 1, 0);
  if (float(k) * dz + dz <= surface) k = min(k + 1, plane_count - 1);
  float z0 = float(k) * dz;
  if (!(z0 < surface && surface < z0 + dz)) SKIP_FRAGMENT
  sum = slab_airlight(pixel, dir, cos_axis, z0, surface);
#else
  float z0 = float(plane) * dz;
#ifdef FULL_SLABS
  if (surface < z0 + dz) SKIP_FRAGMENT  // the surface cuts the slab: CUT_SLABS samples it
#endif
  sum = slab_airlight(pixel, dir, cos_axis, z0, min(z0 + dz, surface));
#endif
  if (sum == vec3(0.0)) discard;
  airlight = vec4(sum, 0.0);
}
