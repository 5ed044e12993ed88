// Nilsson 2008 §3.2 (accumulate=signed): per fragment of a lit pyramid's face,
// ±Γ(0 → min(t, d)) times its weight added into a float target by blending —
// back faces (the ray leaves the pyramid) add, front faces subtract — so that each pixel
// receives Σ over its lit intervals [t_in, t_out] of Γ(0 → t_out) − Γ(0 → t_in).
// With the eye inside a pyramid its front face lies behind the eye, and
// Γ(0 → 0) = 0 is what it would subtract; a face beyond the visible surface
// clamps to it, and its pair with it, cancelling. Unlike the counting
// (lit_intervals.comp.glsl) the sum cancels large terms in float where Γ is
// large (docs/decisions.md).
#define SCENE_IN_REGISTERS
#include "methods/kit/gamma/closed_form.glsl"
#include "methods/kit/counting/crossing_fragment.glsl"

layout(location = 0) out vec4 airlight;

void main() {
  load_scene();
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  FragmentCrossing x;
  if (!fragment_crossing(x)) discard;
  float t = min(x.t, surface_distance(pixel));
  vec3 sum = vec3(0.0);
  if (t > 0.0) {  // behind the eye (or grazing, NaN): Γ(0 → 0) = 0
#define ADD_GAMMA(i) if (x.c.light_weight.x == i) sum = closed_form_airlight(i, frame.eye, x.dir, 0.0, t);
    FOR_EACH_LIGHT(ADD_GAMMA)
#undef ADD_GAMMA
  }
  airlight = vec4(float(x.c.light_weight.y) * (x.facing > 0.0 ? sum : -sum), 0.0);
}
