// in: (axis, tan_cone), (right, layer), (up, -), (dir, -), (lookup uv, the gobo's size)
// → out: (gobo_uv, -, -), (sample_gobo at the lookup uv, -)
#define IN_STRIDE 5
#define OUT_STRIDE 2
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "optics/light.glsl"
layout(binding = 0) uniform sampler2DArray gobos;
void evaluate(uint i) {
  vec4 axis = arg(i, 0), right = arg(i, 1);
  result(i, 0, vec4(gobo_uv(axis.xyz, right.xyz, arg(i, 2).xyz, axis.w, arg(i, 3).xyz), 0.0, 0.0));
  result(i, 1, vec4(sample_gobo(gobos, right.w, ivec2(arg(i, 4).zw), arg(i, 4).xy), 0.0));
}
