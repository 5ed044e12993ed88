// The camera (docs/design.md §5, geometry::primary_ray): pixels, normalized
// device coordinates and view rays, each way, in one place.
#include "methods/kit/frame/scene.glsl"

// The normalized device coordinates of `pixel`, in GL window coordinates
// (origin at the bottom-left corner; a pixel's centre is its integer corner
// + 0.5, as gl_FragCoord.xy). Image row j (top = 0) is GL row height − 1 − j.
vec2 pixel_ndc(vec2 pixel) { return 2.0 * pixel / frame.size - 1.0; }

// The camera ray through normalized device coordinates `ndc`, scaled to unit
// view depth (dot(ray, forward) = 1): the point at view depth z is eye + z·ray.
vec3 view_ray(vec2 ndc) {
  vec2 plane = ndc * frame.tan_half_fov_y * vec2(frame.aspect, 1.0);
  return frame.forward + plane.x * frame.right + plane.y * frame.up;
}

// The unit ray direction through `pixel` (GL window coordinates, as pixel_ndc).
vec3 pixel_ray(vec2 pixel) { return normalize(view_ray(pixel_ndc(pixel))); }

// The normalized device coordinates of the point eye + offset (in front of the
// eye): view_ray inverted.
vec2 ndc_of(vec3 offset) {
  float depth = dot(offset, frame.forward);
  return vec2(dot(offset, frame.right) / frame.aspect, dot(offset, frame.up)) / (depth * frame.tan_half_fov_y);
}

// The GL window coordinates of the point eye + offset (in front of the eye):
// pixel_ray inverted.
vec2 window_of(vec3 offset) { return (ndc_of(offset) + 1.0) * 0.5 * frame.size; }

// The clip-space position of the point at view depth z through `ndc`, as
// frame.view_projection maps it (glm::frustum, kit/frame/uploads.cpp), computed
// without world coordinates: eye + z·ray rounds to the eye's ulp, and a plane
// rasterized just past a near plane of 0.1 mm, 1 m from the origin, fell in
// front of it and was clipped (random scene 75: planes 13 % dark).
vec4 clip_at_depth(vec2 ndc, float z) {
  float n = frame.near_plane, f = frame.far_plane;
  return vec4(ndc * z, ((f + n) * z - 2.0 * f * n) / (f - n), z);
}

// Distance along unit `dir` to the camera's far plane (geometry::far_distance).
float far_plane_distance(vec3 dir) {
  float cos_axis = dot(dir, frame.forward);
  return cos_axis > 0.0 ? frame.far_plane / cos_axis : positive_infinity();
}
