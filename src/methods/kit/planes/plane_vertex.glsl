// What a vertex of a virtual plane hands on (planes.vert.glsl, piece_planes.vert.glsl):
// its clip distances to the light's influence volume, taken at the slab's middle x and
// widened by how far a fragment's sample may lie from it, its plane and ξ.
#include "methods/kit/frame/view_ray.glsl"

uniform vec4 clip_planes[8];  // world half-spaces dot(xyz, x) + w >= 0
uniform int clip_count;
uniform float clip_margin;    // how far a fragment's sample may lie from the slab's middle

out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[8];
};
flat out int plane;
out vec3 xi;

void set_clip_distances(vec3 x) {
  for (int c = 0; c < 8; ++c)
    gl_ClipDistance[c] = c < clip_count ? dot(clip_planes[c].xyz, x) + clip_planes[c].w + clip_margin : 1.0;
}
