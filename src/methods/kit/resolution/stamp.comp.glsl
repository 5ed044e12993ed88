// The coarse grid's distance into its airlight's alpha, after the method has
// written it (ReducedResolution::upsample): the upsampling then reads each
// coarse neighbour in one fetch.
layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup
layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D coarse_distance;
layout(rgba32f, binding = 0) uniform image2D coarse_airlight;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(coarse_airlight)))) return;
  imageStore(coarse_airlight, pixel, vec4(imageLoad(coarse_airlight, pixel).rgb, texelFetch(coarse_distance, pixel, 0).r));
}
