// The airlight-scene/1 format (docs/design.md §4): one reader per section, each
// checking its values' types and ranges and rejecting keys it does not know.
#include "core/image_io.hpp"
#include "scene/camera_limits.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/json_reader.hpp"
#include "scene/light_defaults.hpp"
#include "scene/mesh_build.hpp"
#include "scene/scene_parse.hpp"

#include <airlight/error.hpp>
#include <airlight/scene.hpp>
#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <map>

namespace airlight {
namespace scene_json {
namespace {

using scene_light::default_gobo_up;
using scene_light::parallel;

constexpr const char* kFormat = "airlight-scene/1";

// ---- phase functions -------------------------------------------------------

const std::map<std::string, PhaseType>& phase_types() {
  static const std::map<std::string, PhaseType> types = {
      {"isotropic", PhaseType::isotropic}, {"rayleigh", PhaseType::rayleigh},
      {"henyey_greenstein", PhaseType::henyey_greenstein}, {"schlick", PhaseType::schlick},
      {"hazy", PhaseType::hazy}, {"murky", PhaseType::murky}};
  return types;
}

void add_lobes(const JsonNode& node, float weight, std::vector<PhaseLobe>& lobes);

// A weighted sum: its terms' weights must sum to 1; nested sums multiply out.
void add_sum(JsonObject& o, float weight, std::vector<PhaseLobe>& lobes) {
  const JsonNode terms = o.required("terms");
  const auto elements = terms.elements();
  if (elements.empty()) terms.fail("must list at least one term");
  double total = 0.0;
  for (const JsonNode& element : elements) {
    JsonObject term(element);
    const auto [weight_node, phase] = term.required_all({"weight", "phase"});
    const float w = weight_node.number(closed(0, 1));
    add_lobes(phase, weight * w, lobes);
    term.finish();
    total += w;
  }
  if (std::fabs(total - 1.0) > 1e-4) {
    terms.fail("the weights must sum to 1, not " + number_text(total));
  }
}

void add_lobes(const JsonNode& node, float weight, std::vector<PhaseLobe>& lobes) {
  JsonObject o(node);
  const JsonNode type = o.required("type");
  const std::string name = type.string();
  if (name == "sum") {
    add_sum(o, weight, lobes);
  } else {
    const auto it = phase_types().find(name);
    if (it == phase_types().end()) {
      type.fail("unknown phase function \"" + name +
                "\" (isotropic, rayleigh, henyey_greenstein, schlick, hazy, murky, sum)");
    }
    PhaseLobe lobe{it->second, 0.0f, weight};
    if (lobe.type == PhaseType::henyey_greenstein || lobe.type == PhaseType::schlick) {
      lobe.g = o.required("g").number(open(-1, 1));
    }
    lobes.push_back(lobe);
  }
  o.finish();
}

Phase read_phase(const JsonNode& node) {
  Phase phase;
  phase.lobes.clear();
  add_lobes(node, 1.0f, phase.lobes);
  return phase;
}

Phase read_phase_or_isotropic(JsonObject& o) {
  const auto node = o.optional("phase");
  return node ? read_phase(*node) : Phase{};
}

// ---- camera, medium, light model, volumes -------------------------------------

Camera read_camera(const JsonNode& node) {
  JsonObject o(node);
  Camera c;
  c.position = o.vec3_or("position", c.position);
  c.look_at = o.vec3_or("look_at", c.look_at);
  if (const auto up = o.optional("up")) c.up = up->direction();
  c.fov_y_deg = o.number_or("fov_y_deg", open(0, 180), c.fov_y_deg);
  c.near = o.number_or("near", greater_than(0), c.near);
  c.far = o.number_or("far", greater_than(0), c.far);
  o.finish();
  if (!(c.far > c.near))
    o.fail("far", "must be greater than near (" + number_text(c.near) + "), got " + number_text(c.far));
  if (const std::string problem = scene_camera::depth_range_problem(c); !problem.empty()) o.fail("far", problem);
  const glm::dvec3 view = glm::dvec3(c.look_at) - glm::dvec3(c.position);
  if (!(glm::length(view) > 0.0)) o.fail("look_at", "must differ from position");
  if (parallel(view, glm::dvec3(c.up))) o.fail("up", "must not be parallel to the view direction");
  return c;
}

Medium read_medium(const JsonNode& node) {
  JsonObject o(node);
  Medium m;
  m.sigma_s = o.color_or("scattering", at_least(0), m.sigma_s);
  m.sigma_a = o.color_or("absorption", at_least(0), m.sigma_a);
  m.phase = read_phase_or_isotropic(o);
  o.finish();
  return m;
}

LightModel read_light_model(const JsonNode& node) {
  JsonObject o(node);
  LightModel model;
  const JsonNode type = o.required("type");
  const std::string name = type.string();
  if (name == "simplified") {
    model.type = LightModelType::simplified;
    model.a0 = o.number_or("a0", at_least(0), model.a0);
    model.a1 = o.number_or("a1", at_least(0), model.a1);
    if (model.a0 == 0.0f && model.a1 == 0.0f) node.fail("a0 and a1 must not both be 0");
  } else if (name != "physical") {
    type.fail("must be \"physical\" or \"simplified\"");
  }
  o.finish();
  return model;
}

Volume read_volume(const JsonNode& node) {
  JsonObject o(node);
  const auto [shape, min, max] = o.required_all({"shape", "min", "max"});
  if (shape.string() != "box") shape.fail("must be \"box\" (the only volume shape so far)");
  Volume v;
  v.min = min.vec3();
  v.max = max.vec3();
  if (!glm::all(glm::lessThan(v.min, v.max))) o.fail("max", "must exceed min on every axis");
  v.sigma_s = o.color_or("scattering", at_least(0), v.sigma_s);
  v.sigma_a = o.color_or("absorption", at_least(0), v.sigma_a);
  v.phase = read_phase_or_isotropic(o);
  o.finish();
  return v;
}

// ---- lights ----------------------------------------------------------------

// An image's errors name the image file alone; here they name the light's key too.
std::shared_ptr<const Image> read_gobo(const JsonNode& node, const SceneFiles& files) {
  const std::filesystem::path file = files.dir / node.string();
  if (!files.source.exists(file)) node.fail("file not found: " + file.string());
  std::shared_ptr<const Image> image;
  try {
    image = std::make_shared<const Image>(decode_image(files.source.read(file), file));
  } catch (const InputError& e) {
    node.fail("cannot read " + file.string() + ": " + e.message());
  }
  if (image->empty()) node.fail("the image is empty: " + file.string());
  return image;
}

// gobo_up orients a spot's gobo and a beam (docs/design.md §1): by default world up,
// or +z for an axis (nearly) straight up or down.
void read_gobo_up(JsonObject& o, Light& light) {
  light.gobo_up = default_gobo_up(light.direction);
  if (const auto up = o.optional("gobo_up")) {
    light.gobo_up = up->direction();
    if (parallel(light.gobo_up, light.direction)) up->fail("must not be parallel to direction");
  }
}

void read_spot(JsonObject& o, Light& light, const SceneFiles& files) {
  const auto [position, direction, intensity, cone_deg] =
      o.required_all({"position", "direction", "intensity", "cone_deg"});
  light.position = position.vec3();
  light.direction = direction.direction();
  light.intensity = intensity.color(at_least(0));
  light.cone_deg = cone_deg.number(left_open(0, 180));
  light.edge_deg = o.number_or("edge_deg", closed(0, light.cone_deg), 0.0f);
  read_gobo_up(o, light);
  if (const auto gobo = o.optional("gobo")) {
    // The gobo spans tan(cone_deg): it needs a cone narrower than a hemisphere.
    if (!(light.cone_deg < 90.0f))
      o.fail("cone_deg", "must be < 90 for a spot with a gobo, got " + number_text(light.cone_deg));
    light.gobo = read_gobo(*gobo, files);
  }
}

// A directional light's bounded beam (scene.hpp Beam): every member required.
Beam read_beam(const JsonNode& node) {
  JsonObject o(node);
  Beam beam;
  const auto [origin, size, length] = o.required_all({"origin", "size", "length"});
  beam.origin = origin.vec3();
  beam.size = size.vec2(greater_than(0));
  beam.length = length.number(greater_than(0));
  o.finish();
  return beam;
}

// A directional light lights all of space, or only its beam; gobo_up orients
// the beam, and a gobo spans the beam's aperture, so both need a beam.
void read_directional(JsonObject& o, Light& light, const SceneFiles& files) {
  const auto [direction, irradiance] = o.required_all({"direction", "irradiance"});
  light.direction = direction.direction();
  light.irradiance = irradiance.color(at_least(0));
  const auto beam = o.optional("beam");
  for (const char* key : {"gobo_up", "gobo"})
    if (!beam && o.has(key)) o.fail(key, "needs a \"beam\": on a directional light it applies to the beam's aperture");
  if (!beam) return;
  light.beam = read_beam(*beam);
  read_gobo_up(o, light);
  if (const auto gobo = o.optional("gobo")) light.gobo = read_gobo(*gobo, files);
}

Light read_light(const JsonNode& node, const SceneFiles& files) {
  JsonObject o(node);
  const JsonNode type = o.required("type");
  const std::string name = type.string();
  Light light;
  if (name == "point") {
    light.type = LightType::point;
    const auto [position, intensity] = o.required_all({"position", "intensity"});
    light.position = position.vec3();
    light.intensity = intensity.color(at_least(0));
  } else if (name == "spot") {
    light.type = LightType::spot;
    read_spot(o, light, files);
  } else if (name == "directional") {
    light.type = LightType::directional;
    read_directional(o, light, files);
  } else {
    type.fail("must be \"point\", \"spot\" or \"directional\"");
  }
  if (light.type != LightType::directional && o.has("beam")) o.fail("beam", "only a directional light has a beam");
  o.finish();
  return light;
}

// ---- the scene ---------------------------------------------------------------

// The elements of the optional array `name` (none when it is absent).
std::vector<JsonNode> elements_of(JsonObject& o, std::string_view name) {
  const auto array = o.optional(name);
  return array ? array->elements() : std::vector<JsonNode>{};
}

// "gltf": the .gltf or .glb file, beside this one, whose scene this one starts from.
Scene read_gltf_reference(const JsonNode& node, const SceneFiles& files) {
  const std::filesystem::path file = files.dir / node.string();
  if (!scene_gltf::is_gltf_file(file)) node.fail("must name a .gltf or .glb file");
  if (!files.source.exists(file)) node.fail("file not found: " + file.string());
  return scene_gltf::load_gltf(file, files.source);
}

void check_format(JsonObject& o) {
  const JsonNode format = o.required("format");
  if (format.string() != kFormat) format.fail(std::string("must be \"") + kFormat + "\"");
}

}  // namespace

void read_fog(JsonObject& o, Scene& scene) {
  if (const auto medium = o.optional("medium")) scene.medium = read_medium(*medium);
  if (const auto model = o.optional("light_model")) scene.light_model = read_light_model(*model);
  scene.ambient = o.color_or("ambient", at_least(0), scene.ambient);
  if (const auto volumes = o.optional("volumes")) {
    scene.volumes.clear();
    for (const JsonNode& n : volumes->elements()) scene.volumes.push_back(read_volume(n));
  }
}

Scene parse(const std::string& json_text, const std::filesystem::path& file, const FileSource& source) {
  const std::string file_name = file.string();
  const Json json = parse_json_text(json_text, file_name);
  const JsonNode root(json, file_name, "");
  JsonObject o(root);
  check_format(o);
  const SceneFiles files{file.parent_path(), source};
  // With "gltf" the glTF's meshes, lights, camera and extras come first; the JSON's keys
  // replace them, except lights and objects, which add to them (docs/scene-format.md).
  Scene scene;
  if (const auto gltf = o.optional("gltf")) scene = read_gltf_reference(*gltf, files);
  scene.source = file;
  scene.name = file.stem().string();
  if (const auto name = o.optional("name")) scene.name = name->string();
  if (const auto camera = o.optional("camera")) scene.camera = read_camera(*camera);
  read_fog(o, scene);
  const auto lights = elements_of(o, "lights");
  const auto objects = elements_of(o, "objects");
  o.finish();  // before loading meshes and images: a misspelt key is the cheaper error
  for (const JsonNode& n : lights) scene.lights.push_back(read_light(n, files));
  scene_mesh::TriangleCount triangles;
  for (const Mesh& mesh : scene.meshes) triangles.add(mesh, file_name, "gltf");
  for (const JsonNode& n : objects) {
    scene.meshes.push_back(read_object(n, files));
    triangles.add(scene.meshes.back(), file_name, n.key());
  }
  return scene;
}

}  // namespace scene_json

Scene parse_scene(const std::string& json_text, const std::filesystem::path& file) {
  return scene_json::parse(json_text, file, disk_files());
}

Scene load_scene(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file)) {
    throw InputError(file.string(), "", "cannot read the scene file");
  }
  if (scene_gltf::is_gltf_file(file)) return scene_gltf::load_gltf(file);
  return parse_scene(disk_files().read(file), file);
}

}  // namespace airlight
