#pragma once
// --scene FILE | --builtin NAME, shared by every subcommand that takes a scene.
#include <airlight/scene.hpp>
#include <CLI/CLI.hpp>
#include <string>

namespace airlight::app {

// The scene `scripts/demo` renders, and the viewer's without --scene or --builtin.
inline constexpr const char* default_builtin = "teapot_spot";

struct SceneSource {
  std::string file, builtin;
  void add_options(CLI::App& command);  // exactly one of the two is required
  Scene load() const;
};

// "WxH" with 1 ≤ W, H ≤ 16384; throws InputError(option, text) otherwise.
struct Size {
  int width = 0, height = 0;
};
Size parse_size(const std::string& text, const std::string& option);

}  // namespace airlight::app
