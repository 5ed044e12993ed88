#pragma once
// What a GPU method hands an engine (<airlight/engine.hpp>, docs/design.md §3):
// L_air, T(d) and L_surf·T(d) in the engine's textures, and the composite into
// its colour target.
#include "gpu/timer.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <airlight/engine.hpp>
#include <airlight/method.hpp>

namespace airlight::kit {

// An engine's frame against this frame's inputs, before anything is drawn:
// its targets' sizes and formats, the surface target's needs, one shadow map
// at most per light and no cube map for a directional light.
void check_engine_frame(const EngineFrame& engine, const FrameInputs& inputs);

// L_air (`airlight`, the method's target), T(d) and the frame's L_surf·T(d)
// into the engine's textures (engine_target.comp.glsl), then L = L_surf·T + L_air
// into its colour target by dual-source blending (engine_composite.frag.glsl):
// the engine's colour is only blended into.
void write_engine_target(const EngineTarget& target, const SceneFrame& frame, const Texture& airlight, PassTimer& timer);

}  // namespace airlight::kit
