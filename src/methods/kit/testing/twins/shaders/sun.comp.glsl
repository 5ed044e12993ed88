// in: (σs, σt, I0, d_lv), (γ, d_vp, u, v), (origin, d), (dir, -), (light, -)
// → out: (sun_F(u, v), sun_airlight(σs, σt, I0, d_lv, γ, d_vp), sun_airlight_ray(...), -)
#define IN_STRIDE 5
#define OUT_STRIDE 1
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "optics/sun.glsl"
void evaluate(uint i) {
  vec4 medium = arg(i, 0), angles = arg(i, 1), origin = arg(i, 2);
  float ray = sun_airlight_ray(medium.x, medium.y, medium.z, origin.xyz, arg(i, 3).xyz, arg(i, 4).xyz, origin.w, 0.0);
  result(i, 0, vec4(sun_F(angles.z, angles.w),
                    sun_airlight(medium.x, medium.y, medium.z, medium.w, angles.x, angles.y), ray, 0.0));
}
