#include "app/scene_source.hpp"

#include <airlight/error.hpp>

#include <charconv>

namespace airlight::app {

void SceneSource::add_options(CLI::App& command) {
  auto* scene = command.add_option("--scene", file, "scene file (airlight-scene/1 JSON)");
  auto* named = command.add_option("--builtin", builtin, "built-in scene (airlight list scenes)");
  scene->excludes(named);
  named->excludes(scene);
}

Scene SceneSource::load() const {
  if (file.empty() == builtin.empty()) throw InputError("--scene", "", "give --scene FILE or --builtin NAME");
  return file.empty() ? builtin_scene(builtin, "--builtin") : load_scene(file);
}

namespace {
int parse_dimension(std::string_view text, bool* ok) {
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  *ok = *ok && ec == std::errc() && end == text.data() + text.size() && value >= 1 && value <= 16384;
  return value;
}
}  // namespace

Size parse_size(const std::string& text, const std::string& option) {
  const auto x = text.find('x');
  bool ok = x != std::string::npos;
  Size size;
  if (ok) {
    size.width = parse_dimension(std::string_view(text).substr(0, x), &ok);
    size.height = parse_dimension(std::string_view(text).substr(x + 1), &ok);
  }
  if (!ok) throw InputError(option, text, "expected WxH with 1 ≤ W, H ≤ 16384");
  return size;
}

}  // namespace airlight::app
