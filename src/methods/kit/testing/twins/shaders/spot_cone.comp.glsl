// in: (axis, cone_rad), (dir, edge_rad) → out: (spot_cone, -, -, -)
#define IN_STRIDE 2
#define OUT_STRIDE 1
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "optics/light.glsl"
void evaluate(uint i) {
  vec4 a = arg(i, 0), b = arg(i, 1);
  result(i, 0, vec4(spot_cone(a.xyz, a.w, b.w, b.xyz), 0.0, 0.0, 0.0));
}
