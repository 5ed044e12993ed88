// The start of every per-pixel compute program: its pixel, the bounds check,
// and the view ray with the G-buffer distance along it.
#include "methods/kit/frame/view_ray.glsl"

layout(local_size_x = 8, local_size_y = 8) in;  // gpu::pixel_workgroup, as gpu::dispatch_pixels runs it

#define PIXEL_LIST_READONLY
#include "methods/kit/frame/pixel_list.glsl"

// This invocation's pixel: its global id, or on a sparse grid the pixel
// listed for it.
ivec2 frame_pixel() { return frame.sparse == 0 ? ivec2(gl_GlobalInvocationID.xy) : listed_pixel(); }

// Declares `pixel`, this invocation's pixel in GL window coordinates, and
// returns from main past the frame's edge (the dispatch covers the frame in
// whole workgroups, a sparse grid's list in whole ones too).
#define FRAME_PIXEL_OR_RETURN(pixel)   \
  ivec2 pixel = frame_pixel();        \
  if (any(greaterThanEqual(uvec2(pixel), uvec2(frame_size())))) return

// A pixel's view ray from frame.eye: the unit direction through its centre
// and the G-buffer distance d along it (the visible surface or the far plane).
struct PixelRay {
  vec3 dir;
  float d;
};

// The pixel's ray, after loading the scene into registers (load_scene,
// scene.glsl: nothing without SCENE_IN_REGISTERS) for what follows.
PixelRay load_pixel_ray(ivec2 pixel) {
  load_scene();
  return PixelRay(pixel_ray(vec2(pixel) + 0.5), surface_distance(pixel));
}
