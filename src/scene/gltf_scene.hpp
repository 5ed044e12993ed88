#pragma once
// Internal to the scene layer: glTF 2.0 scenes (docs/scene-format.md "glTF scenes").
#include "core/file_source.hpp"

#include <airlight/scene.hpp>
#include <filesystem>

namespace airlight::scene_gltf {

// Lumens per watt between glTF's photometric light units and airlight's radiometric ones:
// PBR_WATTS_TO_LUMENS of Blender's exporter (io_scene_gltf2/blender/com/
// gltf2_blender_conversion.py), the SI candela's 683 lm/W at 555 nm.
inline constexpr double lumens_per_watt = 683.0;

// A spot's cone and smooth edge (degrees) from glTF's spot.innerConeAngle and
// outerConeAngle (radians, half-angles): the edge spans the angles between the two.
struct SpotCone {
  float cone_deg, edge_deg;
};
SpotCone spot_cone(double inner_cone_angle, double outer_cone_angle);

// Whether `file` is read as glTF: its extension is .gltf or .glb, in any case.
bool is_gltf_file(const std::filesystem::path& file);

// The default scene of a .gltf or .glb file: its meshes, lights and first camera placed by
// their nodes, and the fog of the scene's extras.airlight. Throws InputError naming the file
// and the element. The file and those it names are read from `files`.
Scene load_gltf(const std::filesystem::path& file, const FileSource& files = disk_files());

}  // namespace airlight::scene_gltf
