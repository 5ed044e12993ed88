// The pixels to recompute where the method's result at a pixel reads its
// neighbours' (ReducedResolution::upsample, HALO > 0), a 2×2 block an
// invocation, on the blocks upsample.comp.glsl flagged: a block is listed
// (pixel_list.glsl) when a flagged block lies within BLOCK_HALO blocks
// (Chebyshev), which holds every pixel within HALO pixels of a failed one,
// and a pixel or two more. With MARK the grid's distance too: the
// G-buffer's at the listed pixels, −1 elsewhere. Per block, not per pixel:
// a halo of 3 read 49 texels a pixel, most of the pass on llvmpipe.
#include "methods/kit/frame/pixel_list.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_DISTANCE) uniform sampler2D gbuffer_distance;
layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D failed_blocks;  // > 0 where a pixel of the block failed
#ifdef MARK
layout(r32f, binding = 0) uniform writeonly image2D grid_distance;
#endif

// A pixel at p and a failed one at q, |p − q| ≤ HALO, have blocks at most
// ⌈HALO/2⌉ apart.
const int BLOCK_HALO = (HALO + 1) / 2;

void main() {
  ivec2 block = ivec2(gl_GlobalInvocationID.xy), blocks = textureSize(failed_blocks, 0);
  if (any(greaterThanEqual(block, blocks))) return;
  bool wanted = false;
  for (int y = -BLOCK_HALO; y <= BLOCK_HALO; ++y)
    for (int x = -BLOCK_HALO; x <= BLOCK_HALO; ++x)
      wanted = wanted || texelFetch(failed_blocks, clamp(block + ivec2(x, y), ivec2(0), blocks - 1), 0).r > 0.0;
  ivec2 size = textureSize(gbuffer_distance, 0), first = 2 * block;
  // The block's pixels inside the frame: the last column or row may have one.
  ivec2 span = min(size - first, ivec2(2));
#ifdef MARK
  for (int k = 0; k < 4; ++k) {
    ivec2 pixel = first + ivec2(k & 1, k >> 1);
    if (all(lessThan(pixel, size))) imageStore(grid_distance, pixel, vec4(wanted ? texelFetch(gbuffer_distance, pixel, 0).r : -1.0));
  }
#endif
  if (wanted) {
    uint at = list_room(uint(span.x * span.y));
    for (int k = 0; k < 4; ++k)
      if (all(lessThan(ivec2(k & 1, k >> 1), span))) list_pixel(at++, first + ivec2(k & 1, k >> 1));
  }
}
