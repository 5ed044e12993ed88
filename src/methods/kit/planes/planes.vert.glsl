// Dobashi 2000 §5.1: one virtual plane parallel to the image plane per
// instance, as an n×n lattice mesh over the whole screen. Plane k stands for
// the slab [k·dz, (k+1)·dz] of view depth; it is rasterized at the slab's near
// face, so that the depth test against the scene keeps exactly the slabs that
// begin in front of the visible surface (the fragment shader weighs the part
// in front of it). Clip distances bound it to the light's influence volume:
// the hardware clips the mesh, and fragments outside are never shaded.
//
// With `lattice_xi`, ξ (Dobashi eq. 6: σs·p·exp(−τ)/r² per unit depth, here
// through the shared inscatter without the light map) is evaluated at the
// lattice's vertices at the slab's middle and interpolated across each cell,
// as Gouraud shading did in the paper.
// Specialized as planes.frag.glsl: SHARED_LIGHT, LATTICE_XI (ξ per vertex, else
// per fragment: `xi` unused).
#include "methods/kit/planes/plane_vertex.glsl"

const int light = SHARED_LIGHT;  // its structure's constants; its data are light shared_light's
uniform int lattice;      // cells per side of the mesh
uniform float dz;         // slab thickness in view depth

void main() {
  ivec2 corner = ivec2(gl_VertexID % (lattice + 1), gl_VertexID / (lattice + 1));
  vec2 ndc = 2.0 * vec2(corner) / float(lattice) - 1.0;
  vec3 ray = view_ray(ndc);
  plane = gl_InstanceID;
  vec3 eye = frame.eye;
  // The near face, moved just past the near plane for the first slab (the
  // depth test needs a depth; no surface lies nearer than the near plane).
  float near_face = max(float(plane) * dz, frame.near_plane * 1.0001);
  gl_Position = clip_at_depth(ndc, near_face);
  vec3 x = eye + (float(plane) + 0.5) * dz * ray;
  set_clip_distances(x);
  // Per unit view depth: a step dz in depth is dz·|ray| = dz/cos along the ray
  // (Nilsson ch. 3, footnote 1).
#ifdef LATTICE_XI
  xi = inscatter_unmapped(light, x, normalize(ray), eye_leg_depth(eye, x)) * length(ray);
#else
  xi = vec3(0.0);
#endif
}
