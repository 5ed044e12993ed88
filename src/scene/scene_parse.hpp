#pragma once
// Internal to the scene layer: the readers shared between the scene parser, the
// object parser and the glTF reader.
#include "scene/json_reader.hpp"

#include <airlight/scene.hpp>
#include <filesystem>

namespace airlight::scene_json {

// One entry of "objects" as a mesh in world space; relative mesh paths are
// resolved against `base_dir` (the scene file's folder).
Mesh read_object(const JsonNode& node, const std::filesystem::path& base_dir);

// The fog of a scene: the keys medium, light_model, ambient and volumes of `o` (those the
// object gives replace the scene's), as the top level of a scene file and a glTF's
// extras.airlight give them.
void read_fog(JsonObject& o, Scene& scene);

}  // namespace airlight::scene_json
