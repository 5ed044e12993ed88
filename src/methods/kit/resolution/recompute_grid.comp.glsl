// The grid of the recomputation where the method's result at a pixel reads
// its neighbours' (ReducedResolution::upsample, HALO > 0): the pixels within
// HALO (Chebyshev) of a failed one listed (pixel_list.glsl), and with MARK
// the grid's distance, the G-buffer's there and −1 elsewhere.
#include "methods/kit/frame/pixel_list.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_DISTANCE) uniform sampler2D gbuffer_distance;
layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D failed;  // the failed pixels' distance, −1 elsewhere
#ifdef MARK
layout(r32f, binding = 0) uniform writeonly image2D grid_distance;
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy), size = textureSize(gbuffer_distance, 0);
  if (any(greaterThanEqual(pixel, size))) return;
  bool wanted = false;
  for (int y = -HALO; y <= HALO; ++y)
    for (int x = -HALO; x <= HALO; ++x)
      wanted = wanted || texelFetch(failed, clamp(pixel + ivec2(x, y), ivec2(0), size - 1), 0).r >= 0.0;
#ifdef MARK
  imageStore(grid_distance, pixel, vec4(wanted ? texelFetch(gbuffer_distance, pixel, 0).r : -1.0));
#endif
  if (wanted) list_pixel(list_room(1u), pixel);
}
