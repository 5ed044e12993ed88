#include "app/commands.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>

#include <iostream>
#include <memory>

namespace airlight::app {

namespace {
void list_methods() {
  for (const auto& m : registered_methods()) {
    std::cout << m.name << "\t" << m.source << "\t" << m.description << "\n";
    for (const auto& s : m.settings) std::cout << "    " << s.name << "\t" << s.help << "\n";
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
