// Composite pass: L = L_surf·T(d) + L_air (DESIGN §1).
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform writeonly image2D composite_out;
layout(rgba32f, binding = 1) uniform readonly image2D surface_in;
layout(rgba32f, binding = 2) uniform readonly image2D airlight_in;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, imageSize(composite_out)))) return;
  imageStore(composite_out, pixel, vec4(imageLoad(surface_in, pixel).rgb + imageLoad(airlight_in, pixel).rgb, 1.0));
}
