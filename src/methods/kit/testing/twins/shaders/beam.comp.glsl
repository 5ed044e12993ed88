// in: (origin, length), (axis, width), (right, height), (up, -), (x, -), (dir, t1)
// → out: (beam_uv(x), beam_depth(x), inside_beam(x)), (beam_interval(x, dir, 0, t1), -, -)
#define IN_STRIDE 6
#define OUT_STRIDE 2
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "optics/light.glsl"
void evaluate(uint i) {
  vec4 origin = arg(i, 0), axis = arg(i, 1), right = arg(i, 2);
  Beam b = Beam(origin.xyz, axis.xyz, right.xyz, arg(i, 3).xyz, vec2(axis.w, right.w), origin.w);
  vec3 x = arg(i, 4).xyz;
  result(i, 0, vec4(beam_uv(b, x), beam_depth(b, x), inside_beam(b, x) ? 1.0 : 0.0));
  vec4 ray = arg(i, 5);
  result(i, 1, vec4(beam_interval(b, x, ray.xyz, 0.0, ray.w), 0.0, 0.0));
}
