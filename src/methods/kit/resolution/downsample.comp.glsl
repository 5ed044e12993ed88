// The coarse grid's distance (ReducedResolution::reduce): per coarse pixel,
// the least or the greatest G-buffer distance over the full pixels its
// footprint touches, alternating as a checkerboard (min/max downsampling), so
// that at a silhouette the coarse grid keeps both sides and the upsampling
// finds a neighbour on each. Specialized by DIVISOR (full pixels per coarse
// pixel, per axis).
layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_DISTANCE) uniform sampler2D gbuffer_distance;
layout(r32f, binding = 0) uniform writeonly image2D coarse_distance;

void main() {
  ivec2 coarse = ivec2(gl_GlobalInvocationID.xy), coarse_size = imageSize(coarse_distance);
  if (any(greaterThanEqual(coarse, coarse_size))) return;
  ivec2 full_size = textureSize(gbuffer_distance, 0);
  // The footprint of the coarse pixel on the full grid: both grids span the view (pixel_ndc, view_ray.glsl).
  // DIVISOR pixels from its first: where the sizes do not divide, the footprint
  // is shorter and this takes in a pixel of the next one's, on the safe side.
  // A gather reads each 2×2 of them (the G-buffer's textures clamp to the
  // edge, as min(·, full_size − 1) would): a texel fetch is most of this
  // pass's cost on llvmpipe.
  ivec2 lo = coarse * full_size / coarse_size;
  bool nearest = ((coarse.x + coarse.y) & 1) == 0;
  float d = nearest ? uintBitsToFloat(0x7f800000u) : 0.0;
  for (int y = 0; y < DIVISOR; y += 2)
    for (int x = 0; x < DIVISOR; x += 2) {
      vec4 s = textureGather(gbuffer_distance, (vec2(lo + ivec2(x, y)) + 1.0) / vec2(full_size));
      d = nearest ? min(d, min(min(s.x, s.y), min(s.z, s.w))) : max(d, max(max(s.x, s.y), max(s.z, s.w)));
    }
  imageStore(coarse_distance, coarse, vec4(d));
}
