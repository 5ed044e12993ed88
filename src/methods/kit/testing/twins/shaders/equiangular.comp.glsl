// in: (eye, a), (dir, b), (light, u), (n, even, -, -) → out: (x, weight, θa, θb)
#define IN_STRIDE 4
#define OUT_STRIDE 1
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "methods/kit/sampling/equiangular.glsl"
void evaluate(uint i) {
  vec4 e = arg(i, 0), d = arg(i, 1), l = arg(i, 2), n = arg(i, 3);
  Segment s = n.y != 0.0 ? uniform_segment(e.w, d.w) : equiangular_segment(e.w, d.w, e.xyz, d.xyz, l.xyz);
  result(i, 0, vec4(segment_sample(s, l.w, int(n.x)), s.theta_a, s.theta_b));
}
