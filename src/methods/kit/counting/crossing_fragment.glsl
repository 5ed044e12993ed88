// The fragment stage's side of a counted triangle drawn by crossings.vert.glsl
// (the crossing lists, sv_march's bounds, beam_volumes' signed sum): which
// triangle, whether the pixel's ray passes through it, and where.
#include "methods/kit/frame/view_ray.glsl"
#include "methods/kit/counting/lit_intervals.glsl"

flat in int triangle;
flat in int exact;  // drawn grown: the exact ray test decides (covers)

struct FragmentCrossing {
  CountedTriangle c;
  vec3 dir;      // the pixel's unit ray
  float facing;  // dot(n, dir): > 0 where the ray leaves the triangle's volume
  float t;       // where it meets the triangle's plane (not finite when grazing)
};

// The pixel's ray against the fragment's triangle; false where it does not pass through it.
bool fragment_crossing(out FragmentCrossing x) {
  x.dir = pixel_ray(gl_FragCoord.xy);
  x.c = counted[triangle];
  x.facing = dot(x.c.plane.xyz, x.dir);
  x.t = (x.c.plane.w - dot(x.c.plane.xyz, frame.eye)) / x.facing;
  return covers(exact, x.c, x.dir);
}
