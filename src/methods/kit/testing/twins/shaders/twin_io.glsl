// Shared I/O of the optics twin tests (src/gpu/optics_twin_test.cpp): case i
// reads IN_STRIDE vec4s from `inputs` and writes OUT_STRIDE vec4s to `outputs`.
// The including shader defines IN_STRIDE, OUT_STRIDE and evaluate(), and may
// define TWIN_BINDING (default 0): inputs there, outputs at TWIN_BINDING + 1
// (twins of methods/kit/frame/scene.glsl move them past the frame's storage bindings).
#ifndef TWIN_BINDING
#define TWIN_BINDING 0
#endif
layout(local_size_x = 64) in;
layout(std430, binding = TWIN_BINDING) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = TWIN_BINDING + 1) writeonly buffer Outputs { vec4 outputs[]; };
uniform int count;

vec4 arg(uint i, int k) { return inputs[i * IN_STRIDE + k]; }
void result(uint i, int k, vec4 v) { outputs[i * OUT_STRIDE + k] = v; }

void evaluate(uint i);
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < uint(count)) evaluate(i);
}
