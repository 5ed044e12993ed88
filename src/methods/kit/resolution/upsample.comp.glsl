// The coarse airlight brought to the full grid (ReducedResolution::upsample):
// per full pixel, its four coarse neighbours weighted bilinearly and — with
// BILATERAL — by how close each one's distance lies to the pixel's own
// (joint bilateral upsampling, Kopf et al. 2007, with the G-buffer distance
// as the guide). Where no neighbour lies within reach of the pixel's
// distance, the weights fail; so they do where the neighbours on its side
// disagree (an edge of L_air itself) and within `near_light` pixels of a
// point or spot light's image, where L_air changes by large factors from
// pixel to pixel. Such a pixel is marked, counted, and recomputed on the full
// grid (the value written here is the bilinear one, until then). With HALO 0
// this pass also lists the recomputation's tiles.
#include "methods/kit/frame/tiles.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_DISTANCE) uniform sampler2D gbuffer_distance;
layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D coarse;  // rgb L_air, a the coarse distance (stamp)
layout(rgba32f, binding = 0) uniform writeonly image2D airlight_out;
#ifdef BILATERAL
// The failed pixels' distance, −1 elsewhere: with HALO 0 the recomputation's grid itself.
layout(r32f, binding = 1) uniform writeonly image2D failed_out;
layout(std430, binding = BINDING_RECOMPUTED) buffer Recomputed { uint recomputed; };
layout(std430, binding = BINDING_LIGHT_IMAGES) readonly buffer LightImages { vec2 light_image[]; };
uniform int light_images;  // point and spot lights in front of the camera, in window coordinates
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

Upsampled upsample(ivec2 pixel, ivec2 size, float d, bool near_light_image) {
  ivec2 coarse_size = textureSize(coarse, 0);
  // The pixel's centre on the coarse grid, whose pixel centres sit at integers.
  vec2 at = (vec2(pixel) + 0.5) * vec2(coarse_size) / vec2(size) - 0.5;
  ivec2 base = ivec2(floor(at));
  vec2 f = at - vec2(base);
  vec3 sum = vec3(0.0), plain = vec3(0.0);
  float weight = 0.0, best = 0.0;
  vec3 least = vec3(uintBitsToFloat(0x7f800000u)), greatest = vec3(0.0);
  for (int k = 0; k < 4; ++k) {
    ivec2 o = ivec2(k & 1, k >> 1);
    ivec2 q = clamp(base + o, ivec2(0), coarse_size - 1);
    vec2 axis = mix(vec2(1.0) - f, f, vec2(o));
    vec4 tap = texelFetch(coarse, q, 0);  // one fetch a tap: a texel fetch is most of this pass's cost on llvmpipe
    vec3 value = tap.rgb;
    float w = axis.x * axis.y;
    plain += w * value;
#ifdef BILATERAL
    float gap = abs(tap.a - d) / max(d, 1e-30);
    float depth_weight = exp(-(gap * gap) / (RELATIVE_GAP * RELATIVE_GAP));
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
  bool failed = near_light_image || !(best >= MIN_WEIGHT) || any(lessThan(least, (1.0 - CONTRAST) * greatest));
  return Upsampled(failed ? plain : sum / weight, failed);
#else
  return Upsampled(plain, false);
#endif
}

void upsample_pixel(ivec2 pixel, ivec2 size, bool near_light_image) {
  float d = texelFetch(gbuffer_distance, pixel, 0).r;
  Upsampled u = upsample(pixel, size, d, near_light_image);
  imageStore(airlight_out, pixel, vec4(u.value, 1.0));
#ifdef BILATERAL
  imageStore(failed_out, pixel, vec4(u.failed ? d : -1.0));
#if HALO == 0
  if (u.failed) list_tile(pixel, size.x);
#endif
  if (u.failed) atomicAdd(recomputed, 1u);
#endif
}

// DIVISOR × DIVISOR pixels an invocation, a coarse pixel's worth: on
// llvmpipe an invocation's own cost is a good part of a pass this short.
// Whether a light's image lies within `near_light` pixels (Chebyshev, the
// square the interleaved guard uses too) of the block from `first`: every
// pixel of the block is then recomputed.
bool near_light_image(ivec2 first) {
  bool near = false;
#ifdef BILATERAL
  vec2 centre = vec2(first) + 0.5 * float(DIVISOR);
  for (int i = 0; i < light_images; ++i)
    near = near || all(lessThanEqual(abs(light_image[i] - centre), vec2(near_light + 0.5 * float(DIVISOR))));
#endif
  return near;
}

void main() {
  ivec2 size = textureSize(gbuffer_distance, 0), first = ivec2(gl_GlobalInvocationID.xy) * DIVISOR;
  bool near = near_light_image(first);
  for (int y = 0; y < DIVISOR; ++y)
    for (int x = 0; x < DIVISOR; ++x)
      if (all(lessThan(first + ivec2(x, y), size))) upsample_pixel(first + ivec2(x, y), size, near);
}
