// Shared I/O of the optics twin tests (src/gpu/optics_twin_test.cpp): case i
// reads IN_STRIDE vec4s from `inputs` and writes OUT_STRIDE vec4s to `outputs`.
// The including shader defines IN_STRIDE, OUT_STRIDE and evaluate().
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Inputs { vec4 inputs[]; };
layout(std430, binding = 1) writeonly buffer Outputs { vec4 outputs[]; };
uniform int count;

vec4 arg(uint i, int k) { return inputs[i * IN_STRIDE + k]; }
void result(uint i, int k, vec4 v) { outputs[i * OUT_STRIDE + k] = v; }

void evaluate(uint i);
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < uint(count)) evaluate(i);
}
