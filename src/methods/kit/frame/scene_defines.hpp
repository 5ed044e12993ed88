#pragma once
// The scene's structure as GLSL constants, for SceneFrame::defines() (see
// scene_frame.hpp and docs/design.md §2): light count and kinds, volume count,
// the phase function of constant lobe types, the light model, grey media, and
// FOR_EACH_* macros that unroll loops over lights, volumes and lobes, and
// FOR_EACH_LIGHT_SHARED, one copy per light structure.
#include "methods/kit/frame/frame_data.hpp"

#include <airlight/method.hpp>
#include <string>
#include <vector>

namespace airlight::kit {

std::string structure_defines(const std::vector<shader::SceneLight>& lights,
                              const std::vector<shader::SceneVolume>& volumes,
                              const std::vector<shader::SceneLobe>& lobes, int medium_lobes, const FrameInputs& in);

// Per light, the first light of the same structure (the constants
// structure_defines makes of it): a program compiled for that one light
// serves every light of its structure (scene.glsl, SHARED_LIGHT).
std::vector<int> structure_representatives(const std::vector<shader::SceneLight>& lights);

}  // namespace airlight::kit
