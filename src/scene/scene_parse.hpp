#pragma once
// Internal to the scene layer: the readers shared between the scene parser, the
// object parser and the glTF reader.
#include "core/file_source.hpp"
#include "scene/json_reader.hpp"

#include <airlight/scene.hpp>
#include <filesystem>

namespace airlight::scene_json {

// The files a scene names (meshes, gobos, a glTF): paths relative to `dir`, the
// scene file's folder, read from `source`.
struct SceneFiles {
  std::filesystem::path dir;
  const FileSource& source;
};

// A scene file's text; `file` names it in messages and anchors relative paths.
Scene parse(const std::string& json_text, const std::filesystem::path& file, const FileSource& source);

// One entry of "objects" as a mesh in world space.
Mesh read_object(const JsonNode& node, const SceneFiles& files);

// The fog of a scene: the keys medium, light_model, ambient and volumes of `o` (those the
// object gives replace the scene's), as the top level of a scene file and a glTF's
// extras.airlight give them.
void read_fog(JsonObject& o, Scene& scene);

}  // namespace airlight::scene_json
