// What MarchPass (march_pass.hpp) gives a march program: the jitter tile, the
// steps N and the pixel's own samples of this dispatch (the march is split
// into dispatches of at most 64 samples each, march_pass.cpp).
layout(binding = BINDING_JITTER) uniform sampler2D jitter_offsets;  // R32F tile of values in [0, 1)

uniform int steps;         // N, of the whole march
uniform int first_sample;  // this dispatch: the pixel's own samples j = first_sample ..
uniform int sample_count;  // first_sample + sample_count − 1

// Where in each step this pixel samples, in [0, 1).
float step_offset(ivec2 pixel) {
#ifdef JITTER
  return texelFetch(jitter_offsets, pixel % textureSize(jitter_offsets, 0), 0).r;
#else
  return 0.5;
#endif
}
