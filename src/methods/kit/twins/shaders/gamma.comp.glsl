// methods/kit/closed_form.glsl on the scene the test uploads through kit::SceneFrame.
// in: (eye, light index), (dir, -), (t0, t1, -, -) → out: closed_form_airlight
#define IN_STRIDE 3
#define OUT_STRIDE 1
#include "methods/kit/twins/shaders/twin_io.glsl"
#include "methods/kit/closed_form.glsl"
void evaluate(uint i) {
  vec4 eye = arg(i, 0), t = arg(i, 2);
  result(i, 0, vec4(closed_form_airlight(int(eye.w), eye.xyz, arg(i, 1).xyz, t.x, t.y), 0.0));
}
