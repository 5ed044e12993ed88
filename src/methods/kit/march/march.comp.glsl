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
// reaches the ray. The guide target carries the volume key in w (march.glsl).
// GUARD (interleaved's guard, methods/interleaved/gather.comp.glsl): the march
// also accumulates, per pixel, the squared differences of successive samples'
// terms (march.glsl) in rgb and its own sample count in w, for the gather to
// estimate the standard error of the pixel's own estimate; and a pixel within
// M pixels of a point or spot light's image marches all N samples itself (its
// partial sum is their sum / M², w = PARTIAL_OWN), for the gather to leave it out: there
// L_air changes by large factors from pixel to pixel (the 1/h peak, a gobo's
// stripes converging on the light), and no neighbour's ray stands for it.
// Specialized by MarchPass: SAMPLING (SAMPLING_*), JITTER, NORMALIZED and GUARD.
#define SCENE_IN_REGISTERS
#ifdef GUARD
#define SPREAD
#endif
#include "methods/kit/frame/pixel.glsl"
#include "methods/kit/march/march.glsl"
#include "methods/kit/march/march_pass.glsl"

layout(rgba32f, binding = 0) uniform image2D airlight_out;  // accumulated over the dispatches
#ifdef NORMALIZED
layout(rgba32f, binding = 1) uniform writeonly image2D guide_out;  // the light guide, for the gather to multiply back
#endif
#ifdef GUARD
layout(rgba32f, binding = 2) uniform image2D spread_out;  // accumulated over the dispatches
#endif
uniform int block;  // M: the pixel's own samples j are the indices k = q + j·M²

SampleRange pixel_samples(ivec2 pixel, bool all_samples) {
  int stride = block * block;
  if (all_samples)  // this dispatch's M² strides, every index
    return SampleRange(steps, first_sample * stride, 1, min(steps, (first_sample + sample_count) * stride));
  int q = pixel.x % block + block * (pixel.y % block);
  return SampleRange(steps, q + first_sample * stride, stride, min(steps, q + (first_sample + sample_count) * stride));
}

// Whether point `p` projects within M pixels (in x and in y) of this pixel's
// centre, in front of the camera.
bool near_image(vec3 p, ivec2 pixel) {
  vec3 v = p - frame.eye;
  if (!(dot(v, frame.forward) > 0.0)) return false;
  return all(lessThanEqual(abs(window_of(v) - (vec2(pixel) + 0.5)), vec2(float(block))));
}

bool near_light_image(ivec2 pixel) {
  bool near = false;
#ifdef GUARD
#define OR_NEAR_LIGHT(i) near = near || (light_types[i] != LIGHT_DIRECTIONAL && near_image(LIGHT(i).position, pixel));
  FOR_EACH_LIGHT(OR_NEAR_LIGHT)
#undef OR_NEAR_LIGHT
#endif
  return near;
}

void main() {
  FRAME_PIXEL_OR_RETURN(pixel);
  PixelRay ray = load_pixel_ray(pixel);
  bool keeps_own = near_light_image(pixel);
  SampleRange range = pixel_samples(pixel, keeps_own);
  cut_into_pieces(ray.dir, ray.d);  // for where the steps go (march.glsl)
  vec3 sum = march_airlight(ray.dir, ray.d, range, step_offset(pixel));
  if (keeps_own) sum /= float(block * block);  // as a partial sum: M² times it is the pixel's estimate
#ifdef NORMALIZED
  vec3 guide = light_guide(ray.dir, ray.d);
  imageStore(guide_out, pixel, vec4(guide, volume_key(ray.dir, ray.d)));
  vec4 result = guided(sum, guide);
#else
  vec4 result = vec4(sum, PARTIAL_SHARED);
#endif
  if (keeps_own) result.w = PARTIAL_OWN;
  if (first_sample > 0) result.rgb += imageLoad(airlight_out, pixel).rgb;
  imageStore(airlight_out, pixel, result);
#ifdef GUARD
  vec4 spread = vec4(march_spread, float((max(range.end - range.first, 0) + range.stride - 1) / range.stride));
  if (first_sample > 0) spread += imageLoad(spread_out, pixel);
  imageStore(spread_out, pixel, spread);
#endif
}
