#include "app/commands.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>
#include <airlight/settings.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>

namespace airlight::app {

namespace {
// Each method, then its settings in columns aligned within the method:
//     steps     (integer in [1, 4096], default 64)  samples per ray ...
void list_methods() {
  for (const auto& m : registered_methods()) {
    std::cout << m.name << "\t" << m.source << "\t" << m.description << "\n";
    size_t name_width = 0, values_width = 0;
    for (const auto& s : m.settings) {
      name_width = std::max(name_width, s.name.size());
      values_width = std::max(values_width, describe_values(s).size() + 2);
    }
    for (const auto& s : m.settings)
      std::cout << "    " << std::left << std::setw(int(name_width)) << s.name << "  " << std::setw(int(values_width))
                << "(" + describe_values(s) + ")" << "  " << s.help << "\n";
  }
}
}  // namespace

Run add_list_command(CLI::App& cli) {
  auto* command = cli.add_subcommand("list", "list the methods or the built-in scenes");
  auto what = std::make_shared<std::string>();
  command->add_option("what", *what, "methods | scenes")->required()->check(CLI::IsMember({"methods", "scenes"}));
  return [what] {
    if (*what == "methods") return list_methods();
    for (const auto& name : builtin_scene_names()) std::cout << name << "\t" << builtin_scene_description(name) << "\n";
  };
}

}  // namespace airlight::app
