// The contract's shared functions (<airlight/method.hpp>, docs/design.md §3).
#include <airlight/engine.hpp>
#include <airlight/error.hpp>
#include <airlight/method.hpp>

#include "core/number_text.hpp"
#include "gpu/context.hpp"
#include "scene/camera_limits.hpp"
#include "scene/light_defaults.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <string>
#include <utility>

namespace airlight {

FrameInputs frame_inputs(const Scene& scene, int width, int height) {
  return {scene.camera, width, height, scene.lights, scene.medium, scene.light_model, {}, true};
}

namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void require(bool ok, const std::string& key, const std::string& what) {
  if (!ok) throw InputError("frame", key, what);
}

std::string index(const std::string& key, size_t i) { return key + "[" + std::to_string(i) + "]"; }

// The checks the scene loader makes of a phase function (docs/scene-format.md), per lobe.
void check_phase(const Phase& phase, const std::string& key) {
  double total = 0.0;
  for (size_t k = 0; k < phase.lobes.size(); ++k) {
    const PhaseLobe& lobe = phase.lobes[k];
    const std::string lobe_key = index(key + ".lobes", k);
    require(lobe.g > -1.0f && lobe.g < 1.0f, lobe_key + ".g", "must be in (-1, 1), got " + number_text(lobe.g));
    require(lobe.weight >= 0.0f && lobe.weight <= 1.0f, lobe_key + ".weight",
            "must be in [0, 1], got " + number_text(lobe.weight));
    total += lobe.weight;
  }
  // The loader's tolerance: weights written with four decimals sum to 1.
  require(!phase.lobes.empty() && std::fabs(total - 1.0) <= 1e-4, key + ".lobes",
          "the weights must sum to 1, not " + number_text(total));
}

// gobo_up orients a gobo and a beam (docs/design.md §1): a direction not parallel to the light's.
void check_gobo_up(const Light& light, const std::string& key) {
  require(finite(light.gobo_up) && glm::length(light.gobo_up) > 0.0f, key + ".gobo_up", "must be finite and not zero");
  if (light.gobo || light.beam)
    require(!scene_light::parallel(light.gobo_up, light.direction), key + ".gobo_up",
            "must not be parallel to direction");
}

void check_beam(const Beam& beam, const std::string& key) {
  require(finite(beam.origin), key + ".origin", "must be finite");
  require(beam.size.x > 0.0f && beam.size.y > 0.0f && std::isfinite(beam.size.x) && std::isfinite(beam.size.y),
          key + ".size", "must be finite and > 0, got [" + number_text(beam.size.x) + ", " + number_text(beam.size.y) + "]");
  require(beam.length > 0.0f && std::isfinite(beam.length), key + ".length",
          "must be finite and > 0, got " + number_text(beam.length));
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
  check_gobo_up(light, key);
  if (light.beam) check_beam(*light.beam, key + ".beam");
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
  require(in.camera.near > 0.0f && std::isfinite(in.camera.near), "camera.near",
          "must be finite and > 0, got " + number_text(in.camera.near));
  require(in.camera.far > in.camera.near && std::isfinite(in.camera.far), "camera.far",
          "must be finite and greater than near (" + number_text(in.camera.near) + "), got " +
              number_text(in.camera.far));
  const std::string depth_range = scene_camera::depth_range_problem(in.camera);
  require(depth_range.empty(), "camera.far", depth_range);
  for (size_t i = 0; i < in.lights.size(); ++i) check_light(in.lights[i], index("lights", i));
  const Medium& m = in.medium;
  require(finite(m.sigma_s) && finite(m.sigma_a) && glm::all(glm::greaterThanEqual(m.sigma_s, glm::vec3(0.0f))) &&
              glm::all(glm::greaterThanEqual(m.sigma_a, glm::vec3(0.0f))),
          "medium", "sigma_s and sigma_a must be finite and not negative");
  check_phase(m.phase, "medium.phase");
  for (const auto& [coefficient, name] : {std::pair{in.light_model.a0, "a0"}, std::pair{in.light_model.a1, "a1"}})
    require(coefficient >= 0.0f && std::isfinite(coefficient), std::string("light_model.") + name,
            "must be finite and >= 0, got " + number_text(coefficient));
}

Scene judged_scene(const Scene& scene, const Capabilities& capabilities) {
  Scene judged = scene;
  // Each is another scene: caches keyed by name keep them apart.
  if (!capabilities.volumetric_shadows) {
    for (Mesh& mesh : judged.meshes) mesh.casts_shadows = false;
    judged.name += "_without_shadows";
  }
  if (!capabilities.bounded_volumes && !judged.volumes.empty()) {
    judged.volumes.clear();
    judged.name += "_without_volumes";
  }
  const bool gobos = std::any_of(judged.lights.begin(), judged.lights.end(), [](const Light& l) { return l.gobo; });
  if (!capabilities.gobos && gobos) {
    for (Light& light : judged.lights) light.gobo = nullptr;
    judged.name += "_without_gobos";
  }
  return judged;
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
