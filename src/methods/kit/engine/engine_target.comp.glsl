// An engine's target (kit::GpuMethod, <airlight/engine.hpp>): L_air (or L_surf·T)
// copied into its texture, or with TRANSMITTANCE the eye leg's T(d) = exp(−τ(eye → d)) per
// channel, which compositing L_surf·T + L_air needs. TARGET_FORMAT is the
// engine texture's image format (rgba32f or rgba16f).
#include "methods/kit/frame/scene.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform readonly image2D airlight_in;
layout(TARGET_FORMAT, binding = 1) uniform writeonly image2D target_out;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, frame_size()))) return;
#ifdef TRANSMITTANCE
  vec3 dir = pixel_ray(vec2(pixel) + 0.5);
  vec3 eye = frame.eye;
  imageStore(target_out, pixel, vec4(exp(-eye_leg_depth(eye, eye + surface_distance(pixel) * dir)), 1.0));
#else
  imageStore(target_out, pixel, vec4(imageLoad(airlight_in, pixel).rgb, 1.0));
#endif
}
