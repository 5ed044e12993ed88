// `airlight view` (docs/design.md §5): the options, then the viewer's loop or script.
#include "app/commands.hpp"
#include "app/method_settings.hpp"
#include "app/output_check.hpp"
#include "app/scene_source.hpp"
#include "view/script.hpp"
#include "view/viewer.hpp"

#include <airlight/error.hpp>

#include <fstream>
#include <memory>

namespace airlight::app {
namespace {

struct ViewCommandOptions {
  SceneSource scene;
  std::string method = "raymarch", size = "1024x768", script;
  std::vector<std::string> assignments;
};

void view(ViewCommandOptions o) {
  const Size size = parse_size(o.size, "--size");
  const MethodInfo& info = find_method(o.method, "--method");
  const Settings settings = method_settings(info, o.assignments);  // bad settings exit 2 before a window opens
  if (!o.script.empty() && !std::ifstream(o.script))
    throw InputError("command line", "--script", "cannot read '" + o.script + "'");
  if (o.scene.file.empty() && o.scene.builtin.empty()) o.scene.builtin = default_builtin;
  Scene scene = o.scene.load();
  check_frame_memory(scene, "--size", size, {{&info, &settings}});
  view::Viewer viewer({std::move(scene), o.method, o.assignments, size.width, size.height, o.script.empty()});
  if (!o.script.empty()) view::run_script(viewer, o.script);
  while (viewer.open()) viewer.frame();
}

}  // namespace

Run add_view_command(CLI::App& cli) {
  auto o = std::make_shared<ViewCommandOptions>();
  auto* command = cli.add_subcommand(
      "view", "the interactive viewer: a GPU method live, camera, lights, medium and settings edited (needs a display; "
              "without one: xvfb-run -s \"-screen 0 1280x800x24\" airlight view ...)");
  o->scene.add_options(*command);
  command->add_option("--method", o->method, "GPU method shown first (airlight list methods)")->capture_default_str();
  command->add_option("--set", o->assignments, "method setting key=value (repeatable)");
  command->add_option("--size", o->size, "window size WxH")->capture_default_str();
  command->add_option("--script", o->script, "run the commands of FILE (view/script.hpp), e.g. for tests");
  return [o] { view(*o); };
}

}  // namespace airlight::app
