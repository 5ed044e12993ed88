// L = L_surf·T(d) + L_air into an engine's colour target, which holds L_surf:
// dual-source blending with glBlendFunc(GL_ONE, GL_SRC1_COLOR) multiplies the
// target by the second output (T) and adds the first (L_air), so any
// colour-renderable format works and the engine's colour is never read here.
#include "methods/kit/frame/view_ray.glsl"

layout(binding = BINDING_FIRST_FREE_TEXTURE) uniform sampler2D airlight_in;
layout(location = 0, index = 0) out vec4 out_airlight;
layout(location = 0, index = 1) out vec4 out_transmittance;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  out_airlight = vec4(texelFetch(airlight_in, pixel, 0).rgb, 0.0);
  out_transmittance = vec4(eye_transmittance(pixel_ray(gl_FragCoord.xy), surface_distance(pixel)), 1.0);
}
