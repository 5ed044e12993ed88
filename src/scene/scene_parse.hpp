#pragma once
// Internal to the scene layer: the readers shared between the scene parser and
// the object parser.
#include "scene/json_reader.hpp"

#include <airlight/scene.hpp>
#include <filesystem>

namespace airlight::scene_json {

// One entry of "objects" as a mesh in world space; relative mesh paths are
// resolved against `base_dir` (the scene file's folder).
Mesh read_object(const JsonNode& node, const std::filesystem::path& base_dir);

}  // namespace airlight::scene_json
