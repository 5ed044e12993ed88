#pragma once
// The .glsl files embedded at build time (cmake/embed_shaders.cmake), keyed by
// path: "optics/phase.glsl" for shaders/optics/phase.glsl, and
// "methods/kit/march/march.comp.glsl" for src/methods/kit/march/march.comp.glsl.
#include <map>
#include <string>
#include <string_view>

namespace airlight::gpu {

const std::map<std::string, std::string_view>& embedded_shaders();

}  // namespace airlight::gpu
