// The contract's shared functions (<airlight/method.hpp>, docs/design.md §3).
#include <airlight/engine.hpp>
#include <airlight/error.hpp>
#include <airlight/method.hpp>

#include "gpu/context.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <string>

namespace airlight {

FrameInputs frame_inputs(const Scene& scene, int width, int height) {
  return {scene.camera, width, height, scene.lights, scene.medium, scene.light_model, {}};
}

Scene posed_scene(const Scene& scene, const FrameInputs& inputs) {
  if (!inputs.transforms.empty() && inputs.transforms.size() != scene.meshes.size())
    throw InputError("frame", "transforms",
                     "needs one per mesh (" + std::to_string(scene.meshes.size()) + "), got " +
                         std::to_string(inputs.transforms.size()));
  Scene posed = scene;
  posed.camera = inputs.camera;
  posed.lights = inputs.lights;
  posed.medium = inputs.medium;
  posed.light_model = inputs.light_model;
  for (size_t m = 0; m < inputs.transforms.size(); ++m) {
    const glm::mat4& model = inputs.transforms[m];
    const glm::mat3 normal = glm::transpose(glm::inverse(glm::mat3(model)));
    Mesh& mesh = posed.meshes[m];
    for (glm::vec3& p : mesh.positions) p = glm::vec3(model * glm::vec4(p, 1.0f));
    for (glm::vec3& n : mesh.normals) n = glm::normalize(normal * n);
  }
  return posed;
}

void Method::render_frame(const FrameInputs&, const EngineFrame&) {
  throw Failure("this method runs on the CPU: it cannot render into an engine's GL textures");
}

FrameImages render(Method& method, const Scene& scene, int width, int height) {
  method.render_frame(frame_inputs(scene, width, height));
  return method.read_back();
}

void use_current_gl_context() { gpu::Context::adopt_current(); }

}  // namespace airlight
