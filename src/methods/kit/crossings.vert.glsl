// The counted triangles (lit_intervals.glsl), three vertices each fetched from
// their buffer by gl_VertexID; no vertex attributes. Corners at infinity
// (w = 0, as robust shadow volumes extrude) are projected as they are, so no
// far plane cuts a shadow plane.
#include "methods/kit/scene.glsl"
#include "methods/kit/lit_intervals.glsl"

flat out int triangle;

void main() {
  triangle = gl_VertexID / 3;
  gl_Position = frame.view_projection * counted[triangle].corners[gl_VertexID % 3];
}
