// airlight: renders light shafts by every method and compares them (docs/design.md §5).
#include "app/commands.hpp"
#include "core/interrupt.hpp"

#include <airlight/error.hpp>

#include <cstdio>
#include <map>
#include <string>

namespace {

// Bad input exits 2, any other failure 1 (docs/design.md §5).
enum ExitStatus : int { exit_ok = 0, exit_failure = 1, exit_bad_input = 2 };

int run(int argc, char** argv) {
  CLI::App cli{"airlight: single scattering in participating media, every method against one reference"};
  cli.require_subcommand(1);
  const std::map<std::string, airlight::app::Run> commands{
      {"render", airlight::app::add_render_command(cli)},
      {"list", airlight::app::add_list_command(cli)},
      {"compare", airlight::app::add_compare_command(cli)},
      {"bench", airlight::app::add_bench_command(cli)},
      {"random", airlight::app::add_random_command(cli)},
      {"view", airlight::app::add_view_command(cli)},
  };
  try {
    cli.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return cli.exit(e);  // --help
  } catch (const CLI::ParseError& e) {
    // Bad input in the one form every error has, then where the usage is. CLI11 checks
    // required options before unknown ones, but a misspelt option is the likelier cause
    // ("--ot x.pfm" is not "--out is required").
    std::string message = e.what();
    if (const auto extras = cli.remaining(true); !extras.empty()) {
      message = extras.size() == 1 ? "unknown argument:" : "unknown arguments:";
      for (const auto& extra : extras) message += " " + extra;
    }
    const auto chosen = cli.get_subcommands();
    const std::string command = chosen.empty() ? "airlight" : "airlight " + chosen.front()->get_name();
    std::fprintf(stderr, "airlight: error: %s\nrun '%s --help' for usage\n", message.c_str(), command.c_str());
    return exit_bad_input;
  }
  for (const auto* chosen : cli.get_subcommands()) commands.at(chosen->get_name())();
  return exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
  airlight::remove_unfinished_files_on_interrupt();  // before any thread starts
  try {
    return run(argc, argv);
  } catch (const airlight::InputError& e) {
    std::fprintf(stderr, "airlight: error: %s\n", e.what());
    return exit_bad_input;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "airlight: failure: %s\n", e.what());
    return exit_failure;
  }
}
