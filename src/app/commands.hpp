#pragma once
// The subcommands of `airlight` (docs/design.md §5). Each adds itself to the CLI and
// runs when chosen; errors propagate as InputError (exit 2) or Failure (exit 1).
#include <CLI/CLI.hpp>
#include <functional>

namespace airlight::app {

using Run = std::function<void()>;

// Adds the subcommand to `cli`; the returned function runs it once parsed.
Run add_render_command(CLI::App& cli);
Run add_list_command(CLI::App& cli);
Run add_compare_command(CLI::App& cli);
Run add_bench_command(CLI::App& cli);
Run add_random_command(CLI::App& cli);
// Defined in src/view (the viewer's layer sits on app's).
Run add_view_command(CLI::App& cli);

}  // namespace airlight::app
