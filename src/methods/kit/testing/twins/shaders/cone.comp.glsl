// in: (apex, half_angle), (axis, t0), (origin, t1), (dir, -)
// → out: (count, -, -, -), (piece 0, piece 1) of cone_intervals
#define IN_STRIDE 4
#define OUT_STRIDE 2
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "optics/light.glsl"
void evaluate(uint i) {
  vec4 a = arg(i, 0), b = arg(i, 1), c = arg(i, 2), d = arg(i, 3);
  ConeIntervals lit = cone_intervals(a.xyz, b.xyz, a.w, c.xyz, d.xyz, b.w, c.w);
  result(i, 0, vec4(float(lit.count), 0.0, 0.0, 0.0));
  result(i, 1, vec4(lit.piece[0], lit.piece[1]));
}
