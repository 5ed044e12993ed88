// The recomputed pixels into the upsampled airlight (ReducedResolution::merge),
// over the failed pixels' list: their halo's results read neighbours outside
// the recomputation's grid.
#define PIXEL_LIST_READONLY
#include "methods/kit/frame/pixel_list.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D recomputed;
layout(rgba32f, binding = 0) uniform writeonly image2D airlight_out;

void main() {
  ivec2 pixel = listed_pixel();
  if (pixel.x >= 0) imageStore(airlight_out, pixel, vec4(texelFetch(recomputed, pixel, 0).rgb, 1.0));
}
