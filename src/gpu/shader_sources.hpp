#pragma once
// The .glsl files embedded at build time (cmake/embed_shaders.cmake), keyed by
// path: "optics/phase.glsl" for shaders/optics/phase.glsl, and
// "methods/raymarch/raymarch.comp.glsl" for src/methods/raymarch/raymarch.comp.glsl.
#include <map>
#include <string>
#include <string_view>

namespace airlight::gpu {

const std::map<std::string, std::string_view>& embedded_shaders();

}  // namespace airlight::gpu
