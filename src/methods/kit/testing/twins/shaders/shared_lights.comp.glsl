// FOR_EACH_LIGHT_SHARED of methods/kit/frame/scene.glsl on the scene the test
// uploads through kit::SceneFrame: per case (its input unused) each visit as
// (LIGHT(i).position, i + 64 · LIGHT_DATA(i)), in the order of the visits,
// then for each light k after the loops the same of LIGHT(k), LIGHT_DATA(k).
#define IN_STRIDE 1
#define OUT_STRIDE (2 * LIGHT_COUNT)
#define SCENE_IN_REGISTERS
#include "methods/kit/testing/twins/shaders/twin_io.glsl"
#include "methods/kit/frame/scene.glsl"
void evaluate(uint i) {
  load_scene();
  int n = 0;
#define VISIT(k) result(i, n++, vec4(LIGHT(k).position, float(k + 64 * LIGHT_DATA(k))));
  FOR_EACH_LIGHT_SHARED(VISIT)
  n = LIGHT_COUNT;
  FOR_EACH_LIGHT(VISIT)
#undef VISIT
}
