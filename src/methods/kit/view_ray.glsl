// The camera ray through normalized device coordinates `ndc`, scaled to unit
// view depth (dot(ray, forward) = 1): the point at view depth z is eye + z·ray.
// pixel_ray (methods/kit/scene.glsl) is its direction at a pixel's centre.
#include "methods/kit/scene.glsl"

vec3 view_ray(vec2 ndc) {
  vec2 plane = ndc * frame.tan_half_fov_y * vec2(frame.aspect, 1.0);
  return frame.forward + plane.x * frame.right + plane.y * frame.up;
}
