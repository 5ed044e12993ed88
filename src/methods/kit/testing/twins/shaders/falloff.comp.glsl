// in: (model, r, a1, a0) → out: (light_falloff, -, -, -)
#define IN_STRIDE 1
#define OUT_STRIDE 1
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "optics/light.glsl"
void evaluate(uint i) {
  vec4 a = arg(i, 0);
  result(i, 0, vec4(light_falloff(int(a.x), a.y, a.z, a.w), 0.0, 0.0, 0.0));
}
