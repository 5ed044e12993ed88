// Writes the sources of the fuzz targets' seed corpora, OUT/<target>/<file>, from the
// built-in scenes and the repository's scene, mesh and glTF files (scripts/fuzz
// --merge minimizes them into fuzz/corpus/). Usage: fuzz_seeds SOURCE_DIR OUT_DIR
#include "core/image_io.hpp"
#include "scene/gobo_patterns.hpp"

#include <airlight/scene.hpp>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace fs = std::filesystem;
using Json = nlohmann::json;
using namespace airlight;

namespace {

std::string read(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write(const fs::path& file, const std::string& bytes) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary) << bytes;
}

// A scene's files renamed to the fixed ones beside a fuzz input (fuzz/inputs.cpp).
std::string with_fuzz_files(const std::string& text) {
  Json json = Json::parse(text);
  if (json.contains("gltf")) json["gltf"] = "scene.gltf";
  for (auto& object : json.value("objects", Json::array()))
    if (object.contains("mesh")) object["mesh"] = "cube.obj";
  for (auto& light : json.value("lights", Json::array()))
    if (light.contains("gobo")) light["gobo"] = "gobo.pfm";
  return json.dump();
}

// Meshes larger than this say nothing a small one does not, at a slower pace.
constexpr size_t max_seed_bytes = 16384;

void copy_small(const fs::path& file, const fs::path& out) {
  fs::create_directories(out);
  if (fs::file_size(file) <= max_seed_bytes) fs::copy_file(file, out / file.filename(), fs::copy_options::overwrite_existing);
}

void builtin_scenes(const fs::path& out) {
  const fs::path saved = out / "saved";
  fs::create_directories(saved);
  for (const std::string& name : builtin_scene_names()) {
    save_scene(builtin_scene(name), saved / (name + ".json"));
    write(out / "scene_json" / (name + ".json"), with_fuzz_files(read(saved / (name + ".json"))));
  }
  for (const auto& entry : fs::directory_iterator(saved)) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".obj") copy_small(entry.path(), out / "obj");
    if (ext == ".exr") copy_small(entry.path(), out / "exr");
  }
  fs::remove_all(saved);
}

void repository_files(const fs::path& source, const fs::path& out) {
  for (const char* dir : {"examples/scenes", "examples/scenes/meshes", "tests/data/scenes", "tests/data/gltf",
                          "src/harness/regressions"})
    for (const auto& entry : fs::directory_iterator(source / dir)) {
      const std::string ext = entry.path().extension().string();
      if (ext == ".json") write(out / "scene_json" / entry.path().filename(), with_fuzz_files(read(entry.path())));
      if (ext == ".obj") copy_small(entry.path(), out / "obj");
      if (ext == ".glb") copy_small(entry.path(), out / "gltf");
    }
}

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const size_t n = std::min<size_t>(3, bytes.size() - i);
    unsigned v = 0;
    for (size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (size_t k = 0; k < 4; ++k) text += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return text;
}

// Each .glb as a .gltf too: its JSON chunk, its BIN chunk as the first buffer's data URI.
void gltf_from_glb(const fs::path& out) {
  for (const auto& entry : fs::directory_iterator(out / "gltf")) {
    const std::string glb = read(entry.path());
    std::uint32_t json_length = 0;
    std::memcpy(&json_length, glb.data() + 12, 4);
    Json json = Json::parse(glb.substr(20, json_length));
    const std::string bin = glb.substr(20 + json_length + 8);
    json["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
    write(fs::path(entry.path()).replace_extension(".gltf"), json.dump());
  }
}

// What the repository's glTF files leave out: a camera, KHR_lights_punctual's three lights,
// a strip with indices and normals, a material, the fog in extras.airlight, all in one.
void gltf_features(const fs::path& out) {
  // Four positions, four normals (+z), four uint16 indices.
  std::string bin;
  const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
  const std::uint16_t indices[] = {0, 1, 2, 3};
  bin.append(reinterpret_cast<const char*>(positions), sizeof positions);
  bin.append(reinterpret_cast<const char*>(normals), sizeof normals);
  bin.append(reinterpret_cast<const char*>(indices), sizeof indices);
  const Json json = {
      {"asset", {{"version", "2.0"}}}, {"scene", 0},
      {"scenes", {{{"nodes", {0, 1, 2, 3, 4}}, {"extras", {{"airlight", {{"medium", {{"scattering", 0.1}}}}}}}}}},
      {"nodes",
       {{{"mesh", 0}, {"rotation", {0, 0, 0, 1}}, {"scale", {2, 2, 2}}},
        {{"camera", 0}, {"translation", {0, 0, 5}}},
        {{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}, {"translation", {0, 3, 0}}},
        {{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 2, 2, 1}}},
        {{"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}, {"children", Json::array()}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}, {"mode", 5}, {"material", 0}}}}}}},
      {"materials", {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.6, 0.4, 1}}}}}}},
      {"cameras", {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"zfar", 100}}}}}},
      {"extensionsUsed", {"KHR_lights_punctual"}},
      {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 100}, {"color", {1, 0.9, 0.8}}},
                                                           {{"type", "spot"}, {"intensity", 200}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
                                                           {{"type", "directional"}, {"intensity", 3}}}}}}}},
      {"accessors", {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                     {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}},
                     {{"bufferView", 2}, {"componentType", 5123}, {"count", 4}, {"type", "SCALAR"}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteLength", 48}}, {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 48}},
                       {{"buffer", 0}, {"byteOffset", 96}, {"byteLength", 8}}}},
      {"buffers", {{{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}}}}};
  write(out / "gltf" / "features.gltf", json.dump());
}

void images(const fs::path& out) {
  Image gradient(3, 2);
  for (size_t i = 0; i < gradient.pixels.size(); ++i) gradient.pixels[i] = glm::vec3(float(i) / 5.0f, 0.5f, 1.0f);
  const std::pair<const char*, Image> all[] = {
      {"dots", scene_gobo::polka_dots(16, 4, 0.5f)}, {"glass", scene_gobo::stained_glass(12, 8)}, {"gradient", gradient}};
  for (const auto& [name, image] : all)
    for (const char* format : {"png", "pfm", "exr"}) {
      fs::create_directories(out / format);
      write_image(image, out / format / (std::string(name) + "." + format));
    }
}

// Lines as the README and the command tests give the options.
void method_options(const fs::path& out) {
  const char* lines[] = {
      "--method raymarch\n--set steps=128\n--set sampling=uniform\n",
      "--methods raymarch,planes:planes=50;clip=false\n--set raymarch.jitter=blue\n",
      "--methods raymarch\n--set raymarch.sampling=uniform\n--sweep raymarch.steps=4,16,64\n",
      "--methods reference,planes\n--sweep planes.planes=15,30\n--sweep planes.spacing=0,0.5\n--set reference.rel_tol=1e-4\n",
      "--method planes\n--set planes.lattice=20\n--set shadow_bias=0.5\n"};
  int i = 0;
  for (const char* text : lines) write(out / "method_options" / ("options" + std::to_string(i++) + ".txt"), text);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: fuzz_seeds SOURCE_DIR OUT_DIR\n";
    return 2;
  }
  const fs::path source = argv[1], out = argv[2];
  builtin_scenes(out);
  repository_files(source, out);
  gltf_from_glb(out);
  gltf_features(out);
  images(out);
  method_options(out);
  return 0;
}
