// The built-in scenes by name (airlight/scene.hpp), each with its line for
// `airlight list scenes`; the scenes themselves are in their families' files
// (builtin_families.hpp).
#include "scene/builtin_families.hpp"

#include <airlight/error.hpp>
#include <airlight/scene.hpp>
#include <functional>
#include <map>

namespace airlight {
namespace {

using namespace scene_builtin;

struct Builtin {
  std::function<Scene()> make;
  const char* description;
};

const std::map<std::string, Builtin>& builtins() {
  static const std::map<std::string, Builtin> scenes = {
      {"teapot_spot", {teapot_spot, "Dobashi 2000 Fig. 7a: a teapot on a pedestal clipping one spot's shaft"}},
      {"biri_sphere", {biri_sphere, "Biri 2006 §6: a sphere (32-edge silhouette) beyond a spot, its shadow cutting the beam"}},
      {"biri_pens", {biri_pens, "Biri 2006 Fig. 7a: two crossing pens under a spot, their shadow volumes overlapping"}},
      {"biri_media", {biri_media, "Biri 2006 Fig. 7b: a box under a spot inside red, green and blue bounded media"}},
      {"nilsson_toplight", {nilsson_toplight, "Nilsson 2008 §6 Toplight: a spot from above, orthogonal to the view, over simple objects, simplified light model"}},
      {"nilsson_parallel", {nilsson_parallel, "Nilsson 2008 §6 Parallel: a directional beam nearly along the view through bars, over a box and a sphere"}},
      {"nilsson_multiple", {nilsson_multiple, "Nilsson 2008 §6 Multiple: 25 boxes and spheres in a grid under a spot from above"}},
      {"stage", {stage, "Dobashi 2000 Fig. 7b: five coloured stage spots, some with gobos, seen from the audience, lamps in view"}},
      {"stained_glass", {stained_glass, "Dobashi 2000 Fig. 8b: a sun beam through a stained-glass window into a dusty room"}},
      {"three_lights", {three_lights, "a point light in a cage of pillars, a spot on a sphere and a low sun"}},
      {"toth_hall", {toth_hall, "Tóth 2009 §5: a hall of 66k triangles (arcades, a teapot statue) lit by one point light in fog"}}};
  return scenes;
}

// The entry of `name`; an unknown name is an error of `source`, where the caller got it.
const Builtin& builtin(const std::string& name, const std::string& source) {
  const auto it = builtins().find(name);
  if (it == builtins().end()) {
    std::string known;
    for (const auto& entry : builtins()) known += (known.empty() ? "" : ", ") + entry.first;
    throw InputError(source, name, "unknown built-in scene (known: " + known + ")");
  }
  return it->second;
}

}  // namespace

Scene builtin_scene(const std::string& name, const std::string& source) { return builtin(name, source).make(); }

std::string builtin_scene_description(const std::string& name, const std::string& source) {
  return builtin(name, source).description;
}

std::vector<std::string> builtin_scene_names() {
  std::vector<std::string> names;
  for (const auto& entry : builtins()) names.push_back(entry.first);
  return names;
}

}  // namespace airlight
