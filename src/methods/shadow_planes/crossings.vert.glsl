// Biri §5.1.2: each shadow plane as two triangles, the edge (a, b) and the same
// ends pushed to infinity away from the light (homogeneous w = 0, as robust
// shadow volumes do), so that no far plane cuts it. Six vertices per plane,
// fetched from the plane buffer by gl_VertexID; no vertex attributes.
#include "methods/kit/scene.glsl"
#include "methods/shadow_planes/crossings.glsl"

flat out int plane;

void main() {
  plane = gl_VertexID / 6;
  const int corners[6] = int[6](0, 1, 3, 0, 3, 2);  // a, b, b∞ and a, b∞, a∞
  int corner = corners[gl_VertexID % 6];
  ShadowPlane p = planes[plane];
  int i = int(p.b.w);
  vec3 end = (corner & 1) == 0 ? p.a.xyz : p.b.xyz;
  vec4 x = vec4(end, 1.0);
  if (corner >= 2)  // away from the light: along end − L, or along D for a directional light
    x = vec4(LIGHT(i).type == LIGHT_DIRECTIONAL ? LIGHT(i).direction : end - LIGHT(i).position, 0.0);
  gl_Position = frame.view_projection * x;
}
