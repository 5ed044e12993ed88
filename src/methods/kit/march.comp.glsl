// The march pass of raymarch and interleaved (Tóth 2009 §3.1–4.1, Kingston
// 4.1): per pixel, samples along the view ray from the eye to the G-buffer
// distance d (the visible surface or the far plane), each light's
// in-scattering σs·p·I·V·exp(−τ_light)/r²·exp(−τ_eye) summed with V from the
// light's shadow map or cube map (march.glsl).
//
// Interleaved sampling (Tóth §4.1, Keller & Heidrich 2001) with M×M blocks:
// pixel (x, y) has index q = (x mod M) + M·(y mod M) and marches only the
// samples k ≡ q (mod M²) of the N, writing its partial sum; the gather passes
// (methods/interleaved/) add the block's partial sums. M = 1 is raymarch.
// `normalized`: the partial sums are divided by the pixel's light guide
// (march.glsl) for interleaved's normalized gather; w says whether any light
// reaches the ray.
// Specialized by MarchPass: SAMPLING (SAMPLING_*), JITTER and NORMALIZED.
#define SCENE_IN_REGISTERS
#include "methods/kit/march.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform image2D airlight_out;  // accumulated over the dispatches
#ifdef NORMALIZED
layout(rgba32f, binding = 1) uniform writeonly image2D guide_out;  // the light guide, for the gather to multiply back
#endif
layout(binding = BINDING_JITTER) uniform sampler2D jitter_offsets;  // R32F tile of values in [0, 1)

uniform int steps;         // N, of the whole march
uniform int block;         // M
uniform int first_sample;  // this dispatch: the pixel's own samples j = first_sample ..
uniform int sample_count;  // first_sample + sample_count − 1, i.e. k = q + j·M²

// Where in each step this pixel samples, in [0, 1).
float step_offset(ivec2 pixel) {
#ifdef JITTER
  return texelFetch(jitter_offsets, pixel % textureSize(jitter_offsets, 0), 0).r;
#else
  return 0.5;
#endif
}

SampleRange pixel_samples(ivec2 pixel) {
  int stride = block * block;
  int q = pixel.x % block + block * (pixel.y % block);
  return SampleRange(steps, q + first_sample * stride, stride, min(steps, q + (first_sample + sample_count) * stride));
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, frame_size()))) return;
  load_scene();
  vec3 dir = pixel_ray(vec2(pixel) + 0.5);
  float d = surface_distance(pixel);
  vec3 sum = march_airlight(dir, d, pixel_samples(pixel), step_offset(pixel));
#ifdef NORMALIZED
  vec3 guide = light_guide(dir, d);
  imageStore(guide_out, pixel, vec4(guide, 0.0));
  vec4 result = guided(sum, guide);
#else
  vec4 result = vec4(sum, 1.0);
#endif
  if (first_sample > 0) result.rgb += imageLoad(airlight_out, pixel).rgb;
  imageStore(airlight_out, pixel, result);
}
