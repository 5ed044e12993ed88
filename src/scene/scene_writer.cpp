// Writes a Scene as airlight-scene/1 (docs/design.md §4), the inverse of
// scene_json.cpp: what the viewer saves after editing camera, lights and medium.
// Every mesh is written as an OBJ beside the file in world space (its
// transform already applied, as Scene holds it) and every gobo as a float EXR,
// so nothing is lost: floats print with 9 significant digits, which read back
// to the same float.
#include "core/atomic_file.hpp"
#include "core/image_io.hpp"

#include <airlight/error.hpp>
#include <airlight/scene.hpp>

#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace airlight {
namespace {

using Json = nlohmann::json;

Json vec(const glm::vec3& v) { return Json::array({v.x, v.y, v.z}); }

const char* phase_name(PhaseType type) {
  switch (type) {
    case PhaseType::isotropic: return "isotropic";
    case PhaseType::rayleigh: return "rayleigh";
    case PhaseType::henyey_greenstein: return "henyey_greenstein";
    case PhaseType::schlick: return "schlick";
    case PhaseType::hazy: return "hazy";
    case PhaseType::murky: return "murky";
  }
  return "isotropic";
}

Json lobe_json(const PhaseLobe& lobe) {
  Json j{{"type", phase_name(lobe.type)}};
  if (lobe.type == PhaseType::henyey_greenstein || lobe.type == PhaseType::schlick) j["g"] = lobe.g;
  return j;
}

// One lobe as itself; several as the sum they were flattened from.
Json phase_json(const Phase& phase) {
  if (phase.lobes.size() == 1) return lobe_json(phase.lobes[0]);
  Json terms = Json::array();
  for (const PhaseLobe& lobe : phase.lobes) terms.push_back({{"weight", lobe.weight}, {"phase", lobe_json(lobe)}});
  return {{"type", "sum"}, {"terms", terms}};
}

Json camera_json(const Camera& c) {
  return {{"position", vec(c.position)}, {"look_at", vec(c.look_at)}, {"up", vec(c.up)},
          {"fov_y_deg", c.fov_y_deg},    {"near", c.near},             {"far", c.far}};
}

Json medium_json(const Medium& m) {
  return {{"scattering", vec(m.sigma_s)}, {"absorption", vec(m.sigma_a)}, {"phase", phase_json(m.phase)}};
}

Json volume_json(const Volume& v) {
  return {{"shape", "box"},
          {"min", vec(v.min)},
          {"max", vec(v.max)},
          {"scattering", vec(v.sigma_s)},
          {"absorption", vec(v.sigma_a)},
          {"phase", phase_json(v.phase)}};
}

// Files written beside the scene, named after its stem; a gobo shared by
// several lights is written once.
class SideFiles {
public:
  explicit SideFiles(const std::filesystem::path& scene_file)
      : dir_(scene_file.parent_path()), stem_(scene_file.stem().string()) {}

  std::string gobo(const std::shared_ptr<const Image>& image) {
    auto [it, fresh] = gobos_.try_emplace(image.get(), stem_ + ".gobo" + std::to_string(gobos_.size()) + ".exr");
    if (fresh) write_image(*image, dir_ / it->second);
    return it->second;
  }

  std::string mesh(const Mesh& mesh, size_t index) {
    const std::string name = stem_ + ".mesh" + std::to_string(index) + ".obj";
    write_text_file(dir_ / name, obj_text(mesh));
    return name;
  }

private:
  static std::string obj_text(const Mesh& mesh) {
    std::string text;
    char line[160];
    for (const glm::vec3& p : mesh.positions) {
      std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
      text += line;
    }
    for (const glm::vec3& n : mesh.normals) {
      std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
      text += line;
    }
    for (const glm::uvec3& t : mesh.triangles) {  // OBJ counts from 1; vertex i has normal i
      std::snprintf(line, sizeof line, "f %u//%u %u//%u %u//%u\n", t.x + 1, t.x + 1, t.y + 1, t.y + 1, t.z + 1,
                    t.z + 1);
      text += line;
    }
    return text;
  }

  std::filesystem::path dir_;
  std::string stem_;
  std::map<const Image*, std::string> gobos_;
};

Json light_json(const Light& light, SideFiles& files) {
  Json j;
  switch (light.type) {
    case LightType::point:
      return {{"type", "point"}, {"position", vec(light.position)}, {"intensity", vec(light.intensity)}};
    case LightType::spot:
      j = {{"type", "spot"},           {"position", vec(light.position)}, {"direction", vec(light.direction)},
           {"intensity", vec(light.intensity)}, {"cone_deg", light.cone_deg}, {"edge_deg", light.edge_deg}};
      break;
    case LightType::directional:
      j = {{"type", "directional"}, {"direction", vec(light.direction)}, {"irradiance", vec(light.irradiance)}};
      if (light.beam)
        j["beam"] = {{"origin", vec(light.beam->origin)},
                     {"size", Json::array({light.beam->size.x, light.beam->size.y})},
                     {"length", light.beam->length}};
      break;
  }
  // gobo_up orients a gobo and a beam; written only where the reader accepts it.
  if (light.gobo || light.beam || light.type == LightType::spot) j["gobo_up"] = vec(light.gobo_up);
  if (light.gobo) j["gobo"] = files.gobo(light.gobo);
  return j;
}

// "objects[2] (teapot)" as the loader names a mesh → "teapot"; a built-in's name as it is.
std::string label_of(const std::string& name) {
  const auto open = name.find(" (");
  if (open == std::string::npos || name.back() != ')') return name;
  return name.substr(open + 2, name.size() - open - 3);
}

// Bounding volumes are written only where they are axis-aligned: the format
// gives them as min/max in the object's frame, which for a world-space OBJ is
// the world's. Others are left for geometry/bounding_volumes to compute.
void add_box(Json& object, const char* key, const std::optional<OrientedBox>& box) {
  if (!box || box->axes != glm::mat3(1.0f)) return;
  object[key] = {{"min", vec(box->center - box->half)}, {"max", vec(box->center + box->half)}};
}

Json object_json(const Mesh& mesh, size_t index, SideFiles& files) {
  Json j{{"mesh", files.mesh(mesh, index)},
         {"name", label_of(mesh.name)},
         {"albedo", vec(mesh.albedo)},
         {"casts_shadows", mesh.casts_shadows}};
  add_box(j, "outer_box", mesh.outer_box);
  add_box(j, "inner_box", mesh.inner_box);
  return j;
}

}  // namespace

void save_scene(const Scene& scene, const std::filesystem::path& file) {
  if (file.extension() != ".json") throw InputError(file.string(), "", "a scene is saved as .json");
  SideFiles files(file);
  Json j{{"format", "airlight-scene/1"},
         {"name", scene.name},
         {"camera", camera_json(scene.camera)},
         {"medium", medium_json(scene.medium)},
         {"ambient", vec(scene.ambient)}};
  if (scene.light_model.type == LightModelType::simplified)
    j["light_model"] = {{"type", "simplified"}, {"a0", scene.light_model.a0}, {"a1", scene.light_model.a1}};
  j["volumes"] = Json::array();
  for (const Volume& v : scene.volumes) j["volumes"].push_back(volume_json(v));
  j["lights"] = Json::array();
  for (const Light& light : scene.lights) j["lights"].push_back(light_json(light, files));
  j["objects"] = Json::array();
  for (size_t i = 0; i < scene.meshes.size(); ++i) j["objects"].push_back(object_json(scene.meshes[i], i, files));
  write_text_file(file, j.dump(2) + "\n");
}

}  // namespace airlight
