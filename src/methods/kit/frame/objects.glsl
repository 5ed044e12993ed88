// Each mesh's transform this frame (kit::SceneFrame, FrameInputs::transforms):
// object → world, and its inverse transpose for normals.
#include "methods/kit/frame/scene.glsl"

struct ObjectTransform {
  mat4 model;
  mat4 normal;
};
layout(std430, binding = BINDING_OBJECTS) readonly buffer ObjectTransforms { ObjectTransform objects[]; };
