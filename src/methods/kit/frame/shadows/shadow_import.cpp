#include "methods/kit/frame/scene_frame.hpp"

#include "methods/kit/frame/scene_frame_parts.hpp"
#include "methods/kit/frame/shadows/engine_projection.hpp"

#include <algorithm>
#include <glm/matrix.hpp>

namespace airlight::kit {

using namespace gpu;

// One layer converted from the engine's map: each texel's stored depth turned
// into the distance airlight's lookups compare with (shadow_import.frag.glsl).
void SceneFrame::import_shadow_layer(const ShadowDraw& d) {
  const EngineShadow& e = *d.engine;
  const bool cube = e.kind == EngineShadow::Kind::cube;
  const std::string defines = cube ? "#define ENGINE_CUBE\n" : e.layer >= 0 ? "#define ENGINE_ARRAY\n" : "";
  const Program& program =
      cached_program({{GL_VERTEX_SHADER, "methods/kit/frame/fullscreen.vert.glsl"},
                      {GL_FRAGMENT_SHADER, "methods/kit/frame/shadows/shadow_import.frag.glsl"}},
                     defines_ + defines);
  glUseProgram(program.id());
  set_uniform(program, "light_index", d.light);
  set_uniform(program, "face", d.layer % 6);
  set_uniform(program, "engine_layer", std::max(e.layer, 0));
  set_uniform(program, "engine_distance", e.stores == EngineShadow::Stores::distance ? 1 : 0);
  set_uniform(program, "engine_inverse_view_projection", glm::inverse(cube ? e.projection : d.matrix));
  set_uniform(program, "engine_zero_to_one", e.range == DepthRange::zero_to_one ? 1 : 0);
  set_uniform(program, "engine_far_depth", far_window_depth(e.projection));
  glBindTextureUnit(binding::engine_input, e.texture);
  glBindSampler(binding::engine_input, nearest_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(binding::engine_input, 0);
}

}  // namespace airlight::kit
