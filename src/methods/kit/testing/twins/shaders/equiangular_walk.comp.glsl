// in: (eye, a), (dir, b), (light, offset), (n, stride, k, -) → out: (x, weight, -, -) of
// the walk's sample after k steps from u0 = offset/n by du = stride/n
#define IN_STRIDE 4
#define OUT_STRIDE 1
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "methods/kit/sampling/equiangular.glsl"
void evaluate(uint i) {
  vec4 e = arg(i, 0), d = arg(i, 1), l = arg(i, 2), n = arg(i, 3);
  Segment s = equiangular_segment(e.w, d.w, e.xyz, d.xyz, l.xyz);
  EquiangularWalk w = equiangular_walk(s, l.w / n.x, n.y / n.x, int(n.x));
  for (int k = 0; k < int(n.z); ++k) step_walk(w);
  result(i, 0, vec4(walk_sample(s, w), 0.0, 0.0));
}
