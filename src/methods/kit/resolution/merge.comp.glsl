// The recomputed pixels into the upsampled airlight (ReducedResolution::merge),
// over the recomputation's tiles: only the failed pixels; their halo's
// results read neighbours outside the grid.
#include "methods/kit/frame/tiles.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D failed;  // the failed pixels' distance, −1 elsewhere
layout(binding = BINDING_FIRST_FREE_TEXTURE + 1) uniform sampler2D recomputed;
layout(rgba32f, binding = 0) uniform writeonly image2D airlight_out;

void main() {
  ivec2 pixel = tile_pixel();
  if (any(greaterThanEqual(uvec2(pixel), uvec2(textureSize(recomputed, 0))))) return;
  if (texelFetch(failed, pixel, 0).r >= 0.0) imageStore(airlight_out, pixel, vec4(texelFetch(recomputed, pixel, 0).rgb, 1.0));
}
