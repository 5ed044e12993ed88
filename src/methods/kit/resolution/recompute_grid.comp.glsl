// The grid of the recomputation where the method's result at a pixel reads
// its neighbours' (ReducedResolution::upsample, HALO > 0): the G-buffer
// distance where a failed pixel lies within HALO pixels (Chebyshev), −1
// elsewhere, which FRAME_PIXEL_OR_RETURN (pixel.glsl) skips; and the tiles
// that hold such pixels.
#include "methods/kit/frame/tiles.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_DISTANCE) uniform sampler2D gbuffer_distance;
layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D failed;  // the failed pixels' distance, −1 elsewhere
layout(r32f, binding = 0) uniform writeonly image2D grid_distance;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy), size = textureSize(gbuffer_distance, 0);
  if (any(greaterThanEqual(pixel, size))) return;
  bool wanted = false;
  for (int y = -HALO; y <= HALO; ++y)
    for (int x = -HALO; x <= HALO; ++x)
      wanted = wanted || texelFetch(failed, clamp(pixel + ivec2(x, y), ivec2(0), size - 1), 0).r >= 0.0;
  imageStore(grid_distance, pixel, vec4(wanted ? texelFetch(gbuffer_distance, pixel, 0).r : -1.0));
  if (wanted) list_tile(pixel, size.x);
}
