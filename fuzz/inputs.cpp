#include "inputs.hpp"

#include "app/method_settings.hpp"
#include "core/file_source.hpp"
#include "core/image_io.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/scene_parse.hpp"
#include "scene/shapes.hpp"

#include <airlight/error.hpp>
#include <map>
#include <sstream>

namespace airlight::fuzz {
namespace {

// The folder every input sits in, beside the files a scene may name. They are
// fixed: each format is fuzzed by its own target.
const std::filesystem::path folder = "/fuzz";

const MemoryFiles& siblings() {
  static const MemoryFiles files = [] {
    MemoryFiles f;
    f.add(folder / "cube.obj",
          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
          "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 1 5 8 4\n");
    // A 2x2 gobo: PFM's header, then 4 RGB pixels of little-endian floats.
    std::string pfm = "PF\n2 2\n-1.0\n";
    for (int i = 0; i < 12; ++i) {
      const float v = 0.25f * float(i % 4);
      pfm.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    f.add(folder / "gobo.pfm", pfm);
    // One triangle, its positions in a data URI.
    f.add(folder / "scene.gltf",
          R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
          R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
          R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3"}],)"
          R"("bufferViews":[{"buffer":0,"byteLength":36}],"buffers":[{"byteLength":36,)"
          R"("uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})");
    return f;
  }();
  return files;
}

// The siblings and the input under `name`.
class WithInput : public FileSource {
public:
  WithInput(const std::filesystem::path& name, const std::string& bytes) : name_(name), bytes_(bytes) {}
  bool exists(const std::filesystem::path& file) const override { return file == name_ || siblings().exists(file); }
  std::string read(const std::filesystem::path& file) const override {
    return file == name_ ? bytes_ : siblings().read(file);
  }

private:
  std::filesystem::path name_;
  const std::string& bytes_;
};

template <typename Load>
std::string outcome(Load load) {
  try {
    load();
    return "";
  } catch (const InputError& e) {
    return e.what();
  } catch (const Failure& e) {
    return e.what();
  }
}

std::string scene_json(const std::string& bytes) {
  const auto file = folder / "scene.json";
  return outcome([&] { scene_json::parse(bytes, file, WithInput(file, bytes)); });
}

std::string obj(const std::string& bytes) {
  const auto file = folder / "mesh.obj";
  return outcome([&] { scene_mesh::load_obj(file, WithInput(file, bytes)); });
}

// A .glb starts with its magic "glTF"; anything else is read as a .gltf's JSON.
std::string gltf(const std::string& bytes) {
  const auto file = folder / (bytes.starts_with("glTF") ? "scene.glb" : "scene.gltf");
  return outcome([&] { scene_gltf::load_gltf(file, WithInput(file, bytes)); });
}

template <const char* extension>
std::string image(const std::string& bytes) {
  return outcome([&] { decode_image(bytes, folder / (std::string("gobo") + extension)); });
}
constexpr char png[] = ".png", pfm[] = ".pfm", exr[] = ".exr";

// A command line's method options, one a line: "--method NAME" (render), "--methods
// LIST" (compare's list, bench's names), "--set ASSIGNMENT", "--sweep SWEEP". Each
// command's parser gets them in turn; the outcome is theirs, a line each.
std::string method_options(const std::string& bytes) {
  std::string method, methods;
  std::vector<std::string> listed, sets, sweeps;
  std::istringstream lines(bytes);
  for (std::string line; std::getline(lines, line);) {
    const auto space = line.find(' ');
    const std::string option = line.substr(0, space), value = space == std::string::npos ? "" : line.substr(space + 1);
    if (option == "--method") method = value;
    if (option == "--methods") {
      methods = value;
      for (const auto& name : app::split(value, ',')) listed.push_back(name);
    }
    if (option == "--set") sets.push_back(value);
    if (option == "--sweep") sweeps.push_back(value);
  }
  return "render: " + outcome([&] { app::method_settings(find_method(method, "--method"), sets); }) +
         "\ncompare: " + outcome([&] { app::parse_entries(methods, sets); }) +
         "\nbench: " + outcome([&] { app::plan_variants(listed, sweeps, sets); }) + "\n";
}

}  // namespace

Outcome target(const std::string& name) {
  static const std::map<std::string, Outcome> targets = {
      {"scene_json", scene_json}, {"obj", obj},           {"gltf", gltf},
      {"png", image<png>},        {"pfm", image<pfm>},    {"exr", image<exr>},
      {"method_options", method_options}};
  const auto it = targets.find(name);
  return it == targets.end() ? nullptr : it->second;
}

}  // namespace airlight::fuzz
