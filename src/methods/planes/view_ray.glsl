// The camera ray through normalized device coordinates `ndc`, scaled to unit
// view depth (dot(ray, forward) = 1): the point at view depth z is eye + z·ray.
// pixel_ray (methods/kit/scene.glsl) is its direction at a pixel's centre.
#include "methods/kit/scene.glsl"

vec3 view_ray(vec2 ndc) {
  vec2 plane = ndc * frame_image.z * vec2(frame_image.w, 1.0);
  return frame_forward.xyz + plane.x * frame_right.xyz + plane.y * frame_up.xyz;
}
