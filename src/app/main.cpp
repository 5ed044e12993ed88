// airlight: renders light shafts by every method and compares them (docs/design.md §5).
#include "app/commands.hpp"

#include <airlight/error.hpp>

#include <cstdio>
#include <map>

namespace {

int run(int argc, char** argv) {
  CLI::App cli{"airlight: single scattering in participating media, every method against one reference"};
  cli.require_subcommand(1);
  const std::map<std::string, airlight::app::Run> commands{
      {"render", airlight::app::add_render_command(cli)},
      {"list", airlight::app::add_list_command(cli)},
      {"compare", airlight::app::add_compare_command(cli)},
      {"bench", airlight::app::add_bench_command(cli)},
      {"view", airlight::app::add_view_command(cli)},
  };
  try {
    cli.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return cli.exit(e);  // --help
  } catch (const CLI::ParseError& e) {
    cli.exit(e);  // prints the message and usage
    return airlight::exit_bad_input;
  }
  for (const auto* chosen : cli.get_subcommands()) commands.at(chosen->get_name())();
  return airlight::exit_ok;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const airlight::InputError& e) {
    std::fprintf(stderr, "airlight: error: %s\n", e.what());
    return airlight::exit_bad_input;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "airlight: failure: %s\n", e.what());
    return airlight::exit_failure;
  }
}
