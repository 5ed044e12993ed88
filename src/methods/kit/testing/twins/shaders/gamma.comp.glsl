// methods/kit/gamma/closed_form.glsl on the scene the test uploads through kit::SceneFrame.
// in: (eye, light index), (dir, component phase), (t0, t1, -, -), (component σs, -),
// (component σt, -) → out: closed_form_airlight, or with COMPONENT_TWIN
// component_airlight of that component.
#define IN_STRIDE 5
#define OUT_STRIDE 1
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "methods/kit/gamma/closed_form.glsl"
void evaluate(uint i) {
  vec4 eye = arg(i, 0), dir = arg(i, 1), t = arg(i, 2);
#ifdef COMPONENT_TWIN
  MediumComponent m = MediumComponent(arg(i, 3).xyz, arg(i, 4).xyz, int(dir.w));
  result(i, 0, vec4(component_airlight(int(eye.w), m, eye.xyz, dir.xyz, t.x, t.y), 0.0));
#else
  result(i, 0, vec4(closed_form_airlight(int(eye.w), eye.xyz, dir.xyz, t.x, t.y), 0.0));
#endif
}
