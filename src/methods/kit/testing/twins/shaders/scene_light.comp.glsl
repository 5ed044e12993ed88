// The light side of methods/kit/frame/scene.glsl on the scene the test uploads through
// kit::SceneFrame (its bindings; this shader's I/O at TWIN_BINDING).
// in: (x, light index), (eye, -)
// → out: light_map(x); light_arrival(x): irradiance, distance; to_light;
//   light_arrival_unmapped(x).irradiance; light_leg_depth(x);
//   inscatter and inscatter_unmapped at x seen from eye
#define IN_STRIDE 2
#define OUT_STRIDE 7
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "methods/kit/frame/scene.glsl"
void evaluate(uint i) {
  vec4 x = arg(i, 0);
  vec3 eye = arg(i, 1).xyz;
  int light = int(x.w);
  vec3 view_dir = normalize(x.xyz - eye);
  vec3 eye_depth = eye_leg_depth(eye, x.xyz);
  Arrival a = light_arrival(light, x.xyz);
  result(i, 0, vec4(light_map(light, x.xyz), 0.0));
  result(i, 1, vec4(a.irradiance, isinf(a.distance) ? -1.0 : a.distance));
  result(i, 2, vec4(a.to_light, 0.0));
  result(i, 3, vec4(light_arrival_unmapped(light, x.xyz).irradiance, 0.0));
  result(i, 4, vec4(light_leg_depth(light, x.xyz), 0.0));
  result(i, 5, vec4(inscatter(light, x.xyz, view_dir, eye_depth), 0.0));
  result(i, 6, vec4(inscatter_unmapped(light, x.xyz, view_dir, eye_depth), 0.0));
}
