// sv_march (Kingston 2018 §4.3.2 and §5.3, after McCool 2000): per pixel and
// light, the ray is marched only over [front, back], its first and last
// crossing with the light's shell mesh (kit/light_volume_mesh.hpp: every point
// where the shadow map's visibility can change lies in the shell;
// sv_bounds.frag.glsl). Outside it the visibility is one value on each
// stretch, read at one point of it, and Γ integrates the stretch exactly
// (lit_gamma.glsl; Kingston Fig. 10's cases: lit or unlit before the shell,
// the same after it):
//  - [0, front) and (back, d], where the light reaches along them (a spot's
//    cone lies within its map's frustum; a directional map's column is cut
//    out, lit beside it where the map holds no occluder);
//  - the eye inside the shell: the march starts at the eye.
// The march over [front, back] is raymarch's (march.glsl: its steps N,
// sampling and jitter), per light, N samples over that light's stretch only.
// The exact parts are added by the pass's first dispatch.
#define SCENE_IN_REGISTERS
#include "methods/kit/frame/pixel.glsl"
#include "methods/kit/gamma/lit_gamma.glsl"
#include "methods/kit/march/march.glsl"
#include "methods/kit/march/march_pass.glsl"

layout(rgba32f, binding = 0) uniform image2D airlight_out;  // accumulated over the dispatches
layout(r32ui, binding = 1) readonly uniform uimage2DArray bounds;
// Per light, 0 when the eye is inside its shell (LightVolumeMesh).
layout(std430, binding = BINDING_SHELL_EYE) readonly buffer ShellEye { int shell_eye[]; };

// Where light i's Γ over [a, b] counts whole, no shadow boundary lying there:
// the part the light reaches, weighed by the visibility at its middle; for a
// directional light's map, beside the map's column (nothing occludes there)
// its own stretch and the rest, lit, when the column's middle is in shadow.
// Up to two parts; an empty one has y ≤ x.
struct Unbroken {
  vec2 part[2];
  float visibility;
};
Unbroken unbroken_stretch(int i, vec3 dir, float a, float b) {
  vec3 eye = frame.eye;
  vec2 lit = lit_interval(i, eye, dir, a, b);
  Unbroken whole = Unbroken(vec2[2](lit, vec2(0.0)), 1.0);
  if (!(lit.y > lit.x)) return whole;
  if (light_types[i] == LIGHT_DIRECTIONAL && light_shadows[i] == SHADOW_MAP) {
    vec4 o = LIGHT(i).shadow_matrix * vec4(eye, 1.0), v = LIGHT(i).shadow_matrix * vec4(dir, 0.0);
    vec2 column = box_overlap(vec3(o.xy, 0.0), vec3(v.xy, 0.0), lit.x, lit.y, vec3(-1.0), vec3(1.0));
    if (column.y > column.x && shadow_visibility(i, eye + 0.5 * (column.x + column.y) * dir) == 0.0)
      return Unbroken(vec2[2](vec2(lit.x, column.x), vec2(column.y, lit.y)), 1.0);
    return whole;
  }
  whole.visibility = shadow_visibility(i, eye + 0.5 * (lit.x + lit.y) * dir);
  return whole;
}

// Γ over the unbroken stretches before and after [front, back]: one lit_gamma
// over their up to four parts, in a loop the compiler cannot unroll (each copy
// of Γ costs seconds of llvmpipe's compile; lit_gamma.glsl).
vec3 exact_parts_airlight(int i, vec3 dir, float front, float back, float d) {
  Unbroken before = unbroken_stretch(i, dir, 0.0, front), after = unbroken_stretch(i, dir, back, d);
  vec2 parts[4] = vec2[4](before.part[0], before.part[1], after.part[0], after.part[1]);
  float weights[4] = float[4](before.visibility, before.visibility, after.visibility, after.visibility);
  int count = 0;
  for (int q = 0; q < 4; ++q) count += parts[q].y > parts[q].x && weights[q] > 0.0 ? 1 : 0;
  vec3 sum = vec3(0.0);
  for (int n = 0; n < count; ++n) {
    vec2 part = vec2(0.0);
    float weight = 0.0;
    int seen = 0;
    for (int q = 0; q < 4; ++q)  // the n-th part by selects: indexed by n, Mesa would unroll the loop
      if (parts[q].y > parts[q].x && weights[q] > 0.0 && seen++ == n) {
        part = parts[q];
        weight = weights[q];
      }
    sum += weight * lit_gamma(i, frame.eye, dir, part.x, part.y);
  }
  return sum;
}

// Light i's part of the pixel's ray [0, d]: its samples of this dispatch over
// [front, back], and with `exact_parts` the stretches before and after.
vec3 light_part(int i, ivec2 pixel, vec3 dir, float d, SampleRange r, float offset, bool exact_parts) {
  float front = uintBitsToFloat(imageLoad(bounds, ivec3(pixel, 2 * LIGHT_DATA(i))).r);
  float back = uintBitsToFloat(imageLoad(bounds, ivec3(pixel, 2 * LIGHT_DATA(i) + 1)).r);
  if (shell_eye[LIGHT_DATA(i)] == 0) {
    front = 0.0;
    if (!(back > 0.0)) back = d;  // no crossing found (a closed shell always has one): all of it
  }
  front = min(front, d);
  back = clamp(back, front, d);
  vec3 sum = march_between(i, dir, front, back, r, offset);
  if (exact_parts) sum += exact_parts_airlight(i, dir, front, back, d);
  return sum;
}

void main() {
  FRAME_PIXEL_OR_RETURN(pixel);
  PixelRay ray = load_pixel_ray(pixel);
  SampleRange range = SampleRange(steps, first_sample, 1, min(steps, first_sample + sample_count));
  bool exact_parts = first_sample == 0;
  cut_into_pieces(ray.dir, ray.d);
  float offset = step_offset(pixel);
  vec3 sum = vec3(0.0);
#define ADD_LIGHT(i) sum += light_part(i, pixel, ray.dir, ray.d, range, offset, exact_parts);
  FOR_EACH_LIGHT_SHARED(ADD_LIGHT)
#undef ADD_LIGHT
  if (!exact_parts) sum += imageLoad(airlight_out, pixel).rgb;
  imageStore(airlight_out, pixel, vec4(sum, 1.0));
}
