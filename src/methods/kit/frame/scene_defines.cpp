#include "methods/kit/frame/scene_defines.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

namespace airlight::kit {
namespace {

using shader::SceneLight;
using shader::SceneLobe;
using shader::SceneVolume;

template <typename T>
std::string glsl_array(const char* type, const std::vector<T>& values) {
  std::string text = std::string(type) + "[](";
  if (values.empty()) text += std::is_same_v<T, bool> ? "false" : "0";  // GLSL has no empty arrays
  for (size_t k = 0; k < values.size(); ++k) {
    if (k) text += ", ";
    if constexpr (std::is_same_v<T, bool>)
      text += values[k] ? "true" : "false";
    else
      text += std::to_string(values[k]);
  }
  return text + ")";
}

// FOR_EACH_<WHAT>(F) expands to F(0) F(1) … F(n − 1): loops over lights and
// volumes unrolled by the preprocessor, so that every index is a constant.
std::string for_each(const char* what, size_t n) {
  std::string text = std::string("#define FOR_EACH_") + what + "(F)";
  for (size_t k = 0; k < n; ++k) text += " F(" + std::to_string(k) + ")";
  return text + "\n";
}

// Σ_k weight_k · phase_lobe(type_k, g_k, c) over lobes [first, first + count),
// each type a constant: the phase function a medium has, and nothing else.
std::string phase_expression(const std::vector<SceneLobe>& lobes, int first, int count) {
  std::string text = "(0.0";
  for (int k = first; k < first + count; ++k)
    text += " + LOBE(" + std::to_string(k) + ").weight * phase_lobe(" + std::to_string(lobes[k].type) + ", LOBE(" +
            std::to_string(k) + ").g, c)";
  return text + ")";
}

// Whether lobes [first, first + count) are all isotropic: closed_form.glsl may
// then take Sun et al.'s path.
bool isotropic(const std::vector<SceneLobe>& lobes, int first, int count) {
  for (int k = first; k < first + count; ++k)
    if (lobes[k].type != static_cast<int>(PhaseType::isotropic)) return false;
  return true;
}

bool grey(const glm::vec3& c) { return c.r == c.g && c.g == c.b; }

// What structure_defines makes a constant of a light: its type, smooth edge,
// shadow kind, gobo, beam, and for a spot whether it is narrower than 90°
// (tan_cone > 0: light_record).
std::array<int, 6> structure(const SceneLight& l) {
  return {l.type, l.edge > 0.0f, l.shadow_kind, l.gobo_layer >= 0, l.beam_length > 0.0f, l.tan_cone > 0.0f};
}

// LIGHT_GROUPS declares the lights of each structure that several share,
// ended by −1: light_group_<first>. FOR_EACH_LIGHT_SHARED(F) expands to F(i)
// for a light alone in its structure, and for each group to a loop of F(first)
// that turns the group's lights through slot `first` (scene.glsl swap_lights:
// after n turns each is back in its own). The loop ends at the −1, a bound the
// compiler does not count, so that it does not unroll it back into copies.
std::string shared_light_loops(const std::vector<int>& representatives) {
  std::string groups = "#define LIGHT_GROUPS", loops = "#define FOR_EACH_LIGHT_SHARED(F)";
  for (size_t first = 0; first < representatives.size(); ++first) {
    if (representatives[first] != static_cast<int>(first)) continue;
    const std::string i = std::to_string(first), group = "light_group_" + i;
    std::vector<int> members;
    for (size_t k = first; k < representatives.size(); ++k)
      if (representatives[k] == static_cast<int>(first)) members.push_back(static_cast<int>(k));
    if (members.size() == 1) {
      loops += " F(" + i + ")";
      continue;
    }
    std::string turn;
    for (size_t k = 1; k < members.size(); ++k)
      turn += " swap_lights(" + std::to_string(members[k - 1]) + ", " + std::to_string(members[k]) + ");";
    loops += " for (int k_ = 0; " + group + "[k_] >= 0; ++k_) { F(" + i + ")" + turn + " }";
    members.push_back(-1);
    groups += " const int " + group + "[] = " + glsl_array("int", members) + ";";
  }
  return groups + "\n" + loops + "\n";
}

// What some light of the scene has, and its light model, for #if (scene.glsl):
// a branch no light takes is left out before Mesa inlines it at every call.
std::string presence_defines(const std::vector<int>& types, const std::vector<bool>& edges,
                             const std::vector<bool>& gobos, LightModelType model) {
  const auto has = [&](LightType type, int edge) {  // edge: -1 any, 0 hard, 1 smooth
    for (size_t k = 0; k < types.size(); ++k)
      if (types[k] == static_cast<int>(type) && (edge < 0 || edges[k] == (edge == 1))) return true;
    return false;
  };
  const auto flag = [](const char* name, bool on) { return std::string("#define ") + name + (on ? " 1\n" : " 0\n"); };
  return flag("HAS_POINT_LIGHT", has(LightType::point, -1)) + flag("HAS_SPOT_LIGHT", has(LightType::spot, -1)) +
         flag("HAS_DIRECTIONAL_LIGHT", has(LightType::directional, -1)) +
         flag("HAS_SMOOTH_SPOT", has(LightType::spot, 1)) + flag("HAS_HARD_SPOT", has(LightType::spot, 0)) +
         flag("HAS_GOBO", std::find(gobos.begin(), gobos.end(), true) != gobos.end()) +
         flag("SIMPLIFIED_MODEL", model == LightModelType::simplified);
}

}  // namespace

std::vector<int> structure_representatives(const std::vector<SceneLight>& lights) {
  std::vector<int> first(lights.size());
  for (size_t k = 0; k < lights.size(); ++k) {
    first[k] = static_cast<int>(k);
    for (size_t j = 0; j < k && first[k] == static_cast<int>(k); ++j)
      if (structure(lights[j]) == structure(lights[k])) first[k] = static_cast<int>(j);
  }
  return first;
}

std::string structure_defines(const std::vector<SceneLight>& lights, const std::vector<SceneVolume>& volumes,
                              const std::vector<SceneLobe>& lobes, int medium_lobes, const FrameInputs& in) {
  std::vector<int> types, shadows;
  std::vector<bool> gobos, beams, edges, narrow;
  for (const SceneLight& l : lights) {
    const std::array<int, 6> s = structure(l);
    types.push_back(s[0]);
    edges.push_back(s[1]);
    shadows.push_back(s[2]);
    gobos.push_back(s[3]);
    beams.push_back(s[4]);
    narrow.push_back(s[5]);
  }
  bool grey_media = grey(in.medium.sigma_s) && grey(in.medium.sigma_t());
  for (const SceneVolume& v : volumes) grey_media = grey_media && grey(v.sigma_s) && grey(v.sigma_t);
  std::string d;
  d += "#define LIGHT_COUNT " + std::to_string(lights.size()) + "\n";
  d += "#define VOLUME_COUNT " + std::to_string(volumes.size()) + "\n";
  d += "#define LOBE_COUNT " + std::to_string(lobes.size()) + "\n";
  d += "#define LIGHT_MODEL_TYPE " + std::to_string(static_cast<int>(in.light_model.type)) + "\n";
  d += std::string("#define GREY_MEDIA ") + (grey_media ? "1" : "0") + "\n";
  d += "#define LIGHT_TYPES " + glsl_array("int", types) + "\n";
  d += presence_defines(types, edges, gobos, in.light_model.type);
  d += "#define LIGHT_SHADOWS " + glsl_array("int", shadows) + "\n";
  d += "#define LIGHT_GOBOS " + glsl_array("bool", gobos) + "\n";
  d += "#define LIGHT_BEAMS " + glsl_array("bool", beams) + "\n";
  d += "#define LIGHT_EDGES " + glsl_array("bool", edges) + "\n";
  d += "#define LIGHT_NARROW " + glsl_array("bool", narrow) + "\n";
  std::vector<int> identity(lights.size());
  for (size_t k = 0; k < lights.size(); ++k) identity[k] = static_cast<int>(k);
  d += "#define LIGHT_IDENTITY " + glsl_array("int", identity) + "\n";
  d += shared_light_loops(structure_representatives(lights));
  d += for_each("LIGHT", lights.size()) + for_each("VOLUME", volumes.size()) + for_each("LOBE", lobes.size());
  d += "#define MEDIUM_PHASE(c) " + phase_expression(lobes, 0, medium_lobes) + "\n";
  d += std::string("#define MEDIUM_ISOTROPIC ") + (isotropic(lobes, 0, medium_lobes) ? "1" : "0") + "\n";
  std::string volume_phase = "0.0";  // VOLUME_PHASE(v, c): a chain of constant conditions that folds
  for (size_t v = volumes.size(); v-- > 0;)
    volume_phase = "((v) == " + std::to_string(v) + " ? " +
                   phase_expression(lobes, volumes[v].first_lobe, volumes[v].lobe_count) + " : " + volume_phase + ")";
  d += "#define VOLUME_PHASE(v, c) " + volume_phase + "\n";
  std::string volume_isotropic = "false";  // VOLUME_ISOTROPIC(v): v is one of the isotropic volumes; folds too
  bool any_isotropic = isotropic(lobes, 0, medium_lobes);  // a component may take Sun et al.'s form (#if)
  for (size_t v = 0; v < volumes.size(); ++v)
    if (isotropic(lobes, volumes[v].first_lobe, volumes[v].lobe_count)) {
      volume_isotropic += " || (v) == " + std::to_string(v);
      any_isotropic = true;
    }
  d += "#define VOLUME_ISOTROPIC(v) (" + volume_isotropic + ")\n";
  d += std::string("#define ISOTROPIC_COMPONENTS ") + (any_isotropic ? "1" : "0") + "\n";
  return d;
}

}  // namespace airlight::kit
