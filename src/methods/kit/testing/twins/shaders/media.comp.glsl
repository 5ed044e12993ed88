// in: (a, σt), (b, s), (lo, -), (hi, -), (ray dir, -)
// → out: (box_chord(a, b), box_ray_chord(a, dir), box_contains(a), transmittance(σt, s))
#define IN_STRIDE 5
#define OUT_STRIDE 1
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "optics/media.glsl"
void evaluate(uint i) {
  vec4 a = arg(i, 0), b = arg(i, 1);
  vec3 lo = arg(i, 2).xyz, hi = arg(i, 3).xyz;
  result(i, 0, vec4(box_chord(a.xyz, b.xyz, lo, hi), box_ray_chord(a.xyz, arg(i, 4).xyz, lo, hi),
                    box_contains(a.xyz, lo, hi) ? 1.0 : 0.0, transmittance(vec3(a.w), b.w).x));
}
