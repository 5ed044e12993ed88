// An engine's target (kit::GpuMethod, <airlight/engine.hpp>): L_air (or L_surf·T)
// copied into its texture, or with TRANSMITTANCE the eye leg's T(d) = exp(−τ(eye → d)) per
// channel, which compositing L_surf·T + L_air needs. TARGET_FORMAT is the
// engine texture's image format (rgba32f or rgba16f).
#include "methods/kit/frame/pixel.glsl"

layout(rgba32f, binding = 0) uniform readonly image2D airlight_in;
layout(TARGET_FORMAT, binding = 1) uniform writeonly image2D target_out;

void main() {
  FRAME_PIXEL_OR_RETURN(pixel);
#ifdef TRANSMITTANCE
  PixelRay ray = load_pixel_ray(pixel);
  imageStore(target_out, pixel, vec4(eye_transmittance(ray.dir, ray.d), 1.0));
#else
  imageStore(target_out, pixel, vec4(imageLoad(airlight_in, pixel).rgb, 1.0));
#endif
}
