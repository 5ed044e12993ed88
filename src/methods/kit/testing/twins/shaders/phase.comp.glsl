// in: (type, g, cos θ, -) → out: (phase_lobe, schlick_k(g), -, -)
#define IN_STRIDE 1
#define OUT_STRIDE 1
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "optics/phase.glsl"
void evaluate(uint i) {
  vec4 a = arg(i, 0);
  result(i, 0, vec4(phase_lobe(int(a.x), a.y, a.z), schlick_k(a.y), 0.0, 0.0));
}
