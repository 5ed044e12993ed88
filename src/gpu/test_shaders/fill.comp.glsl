// Writes square(i) * SCALE into element i: checks includes, defines and SSBOs.
#include "gpu/test_shaders/square.glsl"
#include "gpu/test_shaders/square.glsl"
layout(local_size_x = 64) in;
layout(std430, binding = 0) buffer Out { float values[]; };
uniform int count;
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < uint(count)) values[i] = square(float(i)) * SCALE;
}
