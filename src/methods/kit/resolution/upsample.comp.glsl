// The coarse airlight brought to the full grid (ReducedResolution::upsample):
// per full pixel, its four coarse neighbours weighted bilinearly and — with
// BILATERAL — by how close each one's distance lies to the pixel's own
// (joint bilateral upsampling, Kopf et al. 2007, with the G-buffer distance
// as the guide). Where no neighbour lies within reach of the pixel's
// distance, the weights fail; so they do where the neighbours on its side
// disagree (an edge of L_air itself), within `near_light` pixels of a
// light's image (ReducedResolution: a point or spot light, a directional
// light's direction), where L_air changes by large factors from pixel to
// pixel, and beyond the outermost coarse centres. Such a pixel is recomputed
// on the full grid (the value written here is 0 until then): this pass lists
// them (pixel_list.glsl); with MARK it writes their distance, −1 elsewhere,
// and with FLAG_BLOCKS flags each 2×2 block that holds one, for the halo
// around them (recompute_grid.comp.glsl).
#include "methods/kit/frame/pixel_list.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_DISTANCE) uniform sampler2D gbuffer_distance;
layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D coarse;  // rgb L_air, a the coarse distance (stamp)
layout(rgba32f, binding = 0) uniform writeonly image2D airlight_out;
#ifdef MARK
// The failed pixels' distance, −1 elsewhere: the recomputation's grid itself.
layout(r32f, binding = 1) uniform writeonly image2D failed_out;
#endif
#ifdef FLAG_BLOCKS
// Per 2×2 block (an invocation's pixels), 1 where one of them failed.
layout(r32f, binding = 2) uniform writeonly image2D failed_blocks;
#endif
#ifdef BILATERAL
layout(std430, binding = BINDING_LIGHT_IMAGES) readonly buffer LightImages { vec2 light_image[]; };
uniform int light_images;  // where L_air peaks (ReducedResolution's light_images), in window coordinates
uniform float near_light;  // pixels
#endif

// A neighbour's weight falls as exp(−(gap/RELATIVE_GAP)²), gap its distance's
// relative difference from the pixel's; below MIN_WEIGHT it counts as across
// an edge (a gap over 1.5·RELATIVE_GAP). RELATIVE_GAP is wide enough that a
// floor seen at grazing angles, whose distance changes by a few per cent from
// one coarse pixel to the next, keeps its neighbours (docs/decisions.md,
// "Reduced resolution").
const float RELATIVE_GAP = 0.05, MIN_WEIGHT = 0.1;
// The neighbours on the pixel's side of every depth edge disagree when the
// least of them falls below (1 − CONTRAST) of the greatest in some channel: an
// edge of L_air itself (a spot's cone, a shadow's edge, a gobo's stripe) runs
// between them, which no weighting of coarse values places to the pixel.
const float CONTRAST = 0.25;

struct Upsampled {
  vec3 value;
  bool failed;
};

// The pixel's four coarse neighbours, t[j][i] at (base + (i, j)) with base
// the nearest coarse centre below and left of it, and its fraction `f` of the
// way from base to base + (1, 1).
struct Taps {
  vec4 t00, t10, t01, t11;
  vec2 f;
};

// exp(−(gap/RELATIVE_GAP)²) = exp2(gap² · GAP_EXPONENT).
const float GAP_EXPONENT = -1.0 / (RELATIVE_GAP * RELATIVE_GAP * log(2.0));

// A failed pixel's value is left 0: the recomputation writes it. `recompute`
// fails it whatever its neighbours.
Upsampled upsample(Taps taps, float d, bool recompute) {
  vec3 sum = vec3(0.0);
  float weight = 0.0, best = 0.0;
  vec3 least = vec3(uintBitsToFloat(0x7f800000u)), greatest = vec3(0.0);
  float inverse_d = 1.0 / max(d, 1e-30);
#ifdef BILATERAL
  // The pixel lies on the surface its neighbours span when their distances,
  // interpolated to it, give its own: a surface seen at a grazing angle or
  // across a wide view, whose distance changes by more than RELATIVE_GAP
  // from one coarse pixel to the next, is no edge (random scene 38: the far
  // plane of an 86° view at 32×24, which the depth weights alone cut into
  // steps). There the weights are bilinear.
  float planar = mix(mix(taps.t00.a, taps.t10.a, taps.f.x), mix(taps.t01.a, taps.t11.a, taps.f.x), taps.f.y);
  bool on_surface = abs(planar - d) * inverse_d <= RELATIVE_GAP;
#endif
  for (int k = 0; k < 4; ++k) {
    vec2 o = vec2(k & 1, k >> 1);
    vec2 axis = mix(vec2(1.0) - taps.f, taps.f, o);
    vec4 tap = k == 0 ? taps.t00 : k == 1 ? taps.t10 : k == 2 ? taps.t01 : taps.t11;
    vec3 value = tap.rgb;
    float w = axis.x * axis.y;
#ifdef BILATERAL
    float gap = abs(tap.a - d) * inverse_d;
    float depth_weight = on_surface ? 1.0 : exp2(gap * gap * GAP_EXPONENT);
    best = max(best, depth_weight);
    w *= depth_weight;
    if (depth_weight >= MIN_WEIGHT) {
      least = min(least, value);
      greatest = max(greatest, value);
    }
#endif
    sum += w * value;
    weight += w;
  }
#ifdef BILATERAL
  bool failed = recompute || !(best >= MIN_WEIGHT) || any(lessThan(least, (1.0 - CONTRAST) * greatest));
  return Upsampled(failed ? vec3(0.0) : sum / weight, failed);
#else
  return Upsampled(sum, false);
#endif
}

// The taps of `pixel` fetched: any sizes.
Taps fetched_taps(ivec2 pixel, ivec2 size) {
  ivec2 coarse_size = textureSize(coarse, 0);
  // The pixel's centre on the coarse grid, whose pixel centres sit at integers.
  vec2 at = (vec2(pixel) + 0.5) * vec2(coarse_size) / vec2(size) - 0.5;
  ivec2 base = ivec2(floor(at));
  ivec2 hi = coarse_size - 1;
  return Taps(texelFetch(coarse, clamp(base, ivec2(0), hi), 0), texelFetch(coarse, clamp(base + ivec2(1, 0), ivec2(0), hi), 0),
              texelFetch(coarse, clamp(base + ivec2(0, 1), ivec2(0), hi), 0), texelFetch(coarse, clamp(base + 1, ivec2(0), hi), 0),
              at - vec2(base));
}

// Returns whether the pixel, at distance d, failed.
bool upsample_pixel(ivec2 pixel, float d, Taps taps, bool recompute) {
  Upsampled u = upsample(taps, d, recompute);
  imageStore(airlight_out, pixel, vec4(u.value, 1.0));
#ifdef MARK
  imageStore(failed_out, pixel, vec4(u.failed ? d : -1.0));
#endif
  return u.failed;
}

// Whether a light's image lies within `near_light` pixels (Chebyshev, the
// square the interleaved guard uses too) of the 2×2 block from `first`: every
// pixel of the block is then recomputed.
bool near_light_image(ivec2 first) {
  bool near = false;
#ifdef BILATERAL
  vec2 centre = vec2(first) + 1.0;
  for (int i = 0; i < light_images; ++i)
    near = near || all(lessThanEqual(abs(light_image[i] - centre), vec2(near_light + 1.0)));
#endif
  return near;
}

#ifdef EXACT
// Where the sizes divide by DIVISOR, an invocation's 2×2 pixels read the
// coarse pixels around their own at offsets and fractions fixed by their
// place in it: 9 fetches for 4 pixels at 1/2, 4 at 1/4 (texel fetches are
// most of this pass's cost on llvmpipe). A pixel at r within its coarse
// pixel has its base at the coarse pixel − 1 + o, o = (2r ≥ DIVISOR).
const int SPAN = DIVISOR == 2 ? 3 : 2;  // coarse pixels read per axis
vec4 around[SPAN * SPAN];

// The taps of the pixel at r in its coarse pixel, from `around` at k: at 1/2
// r and k are the pixel's place in the invocation, constants once the loops
// are unrolled (an array indexed by a variable is a ladder of selects); at
// 1/4 the invocation's pixels share their taps, k = 0.
Taps block_taps(ivec2 r, ivec2 k) {
  ivec2 o = ivec2(greaterThanEqual(2 * r, ivec2(DIVISOR)));
  vec2 at = (vec2(r) + 0.5) / float(DIVISOR) - 0.5;  // from the coarse pixel's centre
  return Taps(around[SPAN * k.y + k.x], around[SPAN * k.y + k.x + 1], around[SPAN * (k.y + 1) + k.x],
              around[SPAN * (k.y + 1) + k.x + 1], at - vec2(o - 1));
}
#endif

// Whether the pixel lies beyond the outermost coarse centres: with no
// neighbour on its outer side, its clamped taps hold the edge's value flat
// (random scene 38: 13 % short where L_air climbs steeply to the image's
// edge). Such pixels are recomputed: a ring a coarse pixel wide at most.
bool beyond_coarse_centres(ivec2 pixel, ivec2 size) {
#ifdef BILATERAL
  ivec2 coarse_size = textureSize(coarse, 0);
  vec2 at = (vec2(pixel) + 0.5) * vec2(coarse_size) / vec2(size) - 0.5;
  return any(lessThan(at, vec2(0.0))) || any(greaterThan(at, vec2(coarse_size - 1)));
#else
  return false;
#endif
}

// 2×2 pixels an invocation: on llvmpipe an invocation's own cost is a good
// part of a pass this short.
void main() {
  ivec2 size = textureSize(gbuffer_distance, 0), first = ivec2(gl_GlobalInvocationID.xy) * 2;
  if (any(greaterThanEqual(first, size))) return;
  bool near = near_light_image(first);
#ifdef EXACT
  // At 1/2 an invocation is a coarse pixel (r0 = 0); at 1/4 a quarter of one.
  ivec2 coarse_pixel = first / DIVISOR, r0 = DIVISOR == 2 ? ivec2(0) : first % DIVISOR;
  ivec2 hi = textureSize(coarse, 0) - 1;
  ivec2 corner = coarse_pixel - 1 + ivec2(greaterThanEqual(2 * r0, ivec2(DIVISOR)));
  for (int k = 0; k < SPAN * SPAN; ++k)
    around[k] = texelFetch(coarse, clamp(corner + ivec2(k % SPAN, k / SPAN), ivec2(0), hi), 0);
#endif
  // The four pixels' distances in one gather (clamped to the edge, which
  // only pixels past it read): w (0, 0), z (1, 0), x (0, 1), y (1, 1).
  vec4 g = textureGather(gbuffer_distance, vec2(first + 1) / vec2(size));
  vec4 distances = vec4(g.w, g.z, g.x, g.y);
  uint failed = 0u;  // a bit a pixel, 1 << (2y + x)
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 2; ++x) {
      ivec2 pixel = first + ivec2(x, y);
      float d = distances[2 * y + x];
      uint bit = 1u << (2 * y + x);
      bool recompute = near || beyond_coarse_centres(pixel, size);
#ifdef EXACT
      if (upsample_pixel(pixel, d, block_taps(r0 + ivec2(x, y), DIVISOR == 2 ? ivec2(x, y) : ivec2(0)), recompute))
        failed |= bit;
#else
      if (all(lessThan(pixel, size)) && upsample_pixel(pixel, d, fetched_taps(pixel, size), recompute)) failed |= bit;
#endif
    }
#ifdef FLAG_BLOCKS
  imageStore(failed_blocks, first / 2, vec4(failed != 0u ? 1.0 : 0.0));
#endif
#ifdef BILATERAL
  // One atomic an invocation, not one a pixel: on llvmpipe each costs a loop
  // over the lanes whether or not they take it.
  if (failed != 0u) {
    uint at = list_room(uint(bitCount(failed)));
    for (int k = 0; k < 4; ++k)
      if ((failed & (1u << k)) != 0u) list_pixel(at++, first + ivec2(k & 1, k >> 1));
  }
#endif
}
