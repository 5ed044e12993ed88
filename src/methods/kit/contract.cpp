// The contract's shared functions (<airlight/method.hpp>, docs/design.md §3).
#include <airlight/engine.hpp>
#include <airlight/error.hpp>
#include <airlight/method.hpp>

#include "gpu/context.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <string>

namespace airlight {

FrameInputs frame_inputs(const Scene& scene, int width, int height) {
  return {scene.camera, width, height, scene.lights, scene.medium, scene.light_model, {}, true};
}

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw InputError("frame", key, what);
}

void check_light(const Light& light, const std::string& key) {
  require(finite(light.position) && finite(light.direction) && finite(light.intensity) && finite(light.irradiance),
          key, "position, direction and colour must be finite");
  require(glm::length(light.direction) > 0.0f, key + ".direction", "must not be zero");
  require(light.intensity.r >= 0 && light.intensity.g >= 0 && light.intensity.b >= 0 && light.irradiance.r >= 0 &&
              light.irradiance.g >= 0 && light.irradiance.b >= 0,
          key, "colour must not be negative");
  require(light.cone_deg > 0.0f && light.cone_deg <= 180.0f, key + ".cone_deg",
          "must be in (0, 180], got " + std::to_string(light.cone_deg));
  require(light.edge_deg >= 0.0f && light.edge_deg <= light.cone_deg, key + ".edge_deg", "must be in [0, cone_deg]");
}

}  // namespace

void check_frame_inputs(const Scene& scene, const FrameInputs& in) {
  require(in.width > 0 && in.height > 0 && in.width <= 16384 && in.height <= 16384, "size",
          "must be 1 to 16384 pixels per side, got " + std::to_string(in.width) + "x" + std::to_string(in.height));
  require(in.transforms.empty() || in.transforms.size() == scene.meshes.size(), "transforms",
          "needs one per mesh (" + std::to_string(scene.meshes.size()) + "), got " +
              std::to_string(in.transforms.size()));
  for (size_t m = 0; m < in.transforms.size(); ++m)
    for (int c = 0; c < 4; ++c)
      require(finite(glm::vec3(in.transforms[m][c])) && std::isfinite(in.transforms[m][c].w),
              "transforms[" + std::to_string(m) + "]", "must be finite");
  require(finite(in.camera.position) && finite(in.camera.look_at) && finite(in.camera.up), "camera",
          "position, look_at and up must be finite");
  for (size_t i = 0; i < in.lights.size(); ++i) check_light(in.lights[i], "lights[" + std::to_string(i) + "]");
  const Medium& m = in.medium;
  require(finite(m.sigma_s) && finite(m.sigma_a) && glm::all(glm::greaterThanEqual(m.sigma_s, glm::vec3(0.0f))) &&
              glm::all(glm::greaterThanEqual(m.sigma_a, glm::vec3(0.0f))),
          "medium", "sigma_s and sigma_a must be finite and not negative");
}

Scene posed_scene(const Scene& scene, const FrameInputs& inputs) {
  check_frame_inputs(scene, inputs);
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

FrameImages render(Method& method, const Scene& scene, int width, int height, bool surface) {
  FrameInputs inputs = frame_inputs(scene, width, height);
  inputs.surface = surface;
  method.render_frame(inputs);
  return method.read_back();
}

void use_current_gl_context() { gpu::Context::adopt_current(); }

}  // namespace airlight
