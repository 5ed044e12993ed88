// Nilsson 2008 §5.3: the parts of the virtual planes cut by a light's regions
// (slab_regions.hpp), one triangle list of world positions at their slabs'
// middles. Rasterized there — nearer than the slab's far face by dz/2, far more
// than the depth buffer's resolution, so the depth test keeps every slab wholly
// in front of the surface (planes.frag.glsl FULL_SLABS drops the rest) — or
// just past the near plane when the middle lies in front of it. Clip distances
// as planes.vert.glsl.
#include "methods/kit/view_ray.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in int slab;
uniform vec4 clip_planes[8];  // world half-spaces dot(xyz, x) + w >= 0
uniform int clip_count;
uniform float clip_margin;    // how far a fragment's sample may lie from the slab's middle

out gl_PerVertex {
  vec4 gl_Position;
  float gl_ClipDistance[8];
};
flat out int plane;
out vec3 xi;

void main() {
  plane = slab;
  xi = vec3(0.0);
  vec3 eye = frame.eye;
  float depth = dot(position - eye, frame.forward);
  float raster = max(depth, frame.near_plane * 1.0001);
  gl_Position = frame.view_projection * vec4(eye + (position - eye) * (raster / depth), 1.0);
  for (int c = 0; c < 8; ++c)
    gl_ClipDistance[c] = c < clip_count ? dot(clip_planes[c].xyz, position) + clip_planes[c].w + clip_margin : 1.0;
}
