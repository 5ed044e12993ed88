// Nilsson 2008 §5.3: the pieces of the virtual planes cut by a light's regions
// (slab_pieces.hpp), one triangle list of world positions at their slabs'
// middles. Rasterized there — nearer than the slab's far face by dz/2, far more
// than the depth buffer's resolution, so the depth test keeps every slab wholly
// in front of the surface (planes.frag.glsl FULL_SLABS drops the rest) — or
// just past the near plane when the middle lies in front of it.
#include "methods/kit/planes/plane_vertex.glsl"

layout(location = 0) in vec3 position;
layout(location = 1) in int slab;

void main() {
  plane = slab;
  xi = vec3(0.0);
  vec3 eye = frame.eye;
  float depth = dot(position - eye, frame.forward);
  float raster = max(depth, frame.near_plane * 1.0001);
  gl_Position = clip_at_depth(ndc_of(position - eye), raster);
  set_clip_distances(position);
}
