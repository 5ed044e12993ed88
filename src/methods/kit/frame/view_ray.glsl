// The camera ray through normalized device coordinates `ndc`, scaled to unit
// view depth (dot(ray, forward) = 1): the point at view depth z is eye + z·ray.
// pixel_ray (methods/kit/frame/scene.glsl) is its direction at a pixel's centre.
#include "methods/kit/frame/scene.glsl"

vec3 view_ray(vec2 ndc) {
  vec2 plane = ndc * frame.tan_half_fov_y * vec2(frame.aspect, 1.0);
  return frame.forward + plane.x * frame.right + plane.y * frame.up;
}

// The clip-space position of the point at view depth z through `ndc`, as
// frame.view_projection maps it (glm::frustum, kit/frame/uploads.cpp), computed
// without world coordinates: eye + z·ray rounds to the eye's ulp, and a plane
// rasterized just past a near plane of 0.1 mm, 1 m from the origin, fell in
// front of it and was clipped (random scene 75: planes 13 % dark).
vec4 clip_at_depth(vec2 ndc, float z) {
  float n = frame.near_plane, f = frame.far_plane;
  return vec4(ndc * z, ((f + n) * z - 2.0 * f * n) / (f - n), z);
}

// The normalized device coordinates of the point eye + offset (in front of the eye).
vec2 ndc_of(vec3 offset) {
  float depth = dot(offset, frame.forward);
  return vec2(dot(offset, frame.right) / frame.aspect, dot(offset, frame.up)) / (depth * frame.tan_half_fov_y);
}
