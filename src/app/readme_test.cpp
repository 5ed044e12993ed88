// README.md as a new user reads it (issue 15): its commands run as printed and
// its example messages are the ones the command really prints.
#include "app/command_test_support.hpp"

#include <map>
#include <regex>
#include <set>

namespace airlight {
namespace {

using namespace test;

const std::string readme = read_text(source_dir() / "README.md");

// The commands of README's indented code blocks, continuation lines joined,
// split into words as the shell would (single quotes group).
std::vector<std::vector<std::string>> readme_commands() {
  std::vector<std::vector<std::string>> commands;
  std::istringstream lines(readme);
  std::string command;
  for (std::string line; std::getline(lines, line);) {
    if (command.empty()) {
      const size_t start = line.find_first_not_of(' ');
      if (start < 4 || start == std::string::npos) continue;
      line = line.substr(start);
      if (line.rfind("airlight ", 0) != 0 && line.rfind("build/release/src/app/airlight ", 0) != 0) continue;
    }
    const bool continued = !line.empty() && line.back() == '\\';
    command += continued ? line.substr(0, line.size() - 1) : line;
    if (continued) continue;
    std::vector<std::string> words;
    std::string word;
    bool quoted = false, in_word = false;
    for (const char c : command.substr(0, command.find("  #"))) {
      if (c == '\'') quoted = !quoted, in_word = true;
      else if (c == ' ' && !quoted) {
        if (in_word) words.push_back(word);
        word.clear(), in_word = false;
      } else word += c, in_word = true;
    }
    if (in_word) words.push_back(word);
    commands.push_back(words);
    command.clear();
  }
  return commands;
}

// Runs `airlight` with `args` in `dir`.
Outcome run_in(const fs::path& dir, const std::string& args, const std::string& env = "") {
  const fs::path out = work_dir() / "readme_stdout.txt", err = work_dir() / "readme_stderr.txt";
  const std::string command = "cd " + dir.string() + " && " + (env.empty() ? "" : "env " + env + " ") +
                              airlight_exe().string() + " " + args + " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(out), read_text(err)};
}

// How README says to call the command: installed (on PATH), or by its build path.
TEST(Readme, SaysHowTheCommandGetsOnThePath) {
  EXPECT_NE(readme.find("cmake --install build/release"), std::string::npos);
  bool bare = false;
  for (const auto& words : readme_commands()) bare = bare || words.at(0) == "airlight";
  EXPECT_TRUE(bare) << "README calls the installed command airlight";
}

// Every option a README command passes is one its subcommand has, and nothing
// is pasted with the brackets of a usage line.
TEST(Readme, CommandsUseOnlyOptionsTheirSubcommandHas) {
  const auto commands = readme_commands();
  ASSERT_GE(commands.size(), 5u);
  std::map<std::string, std::string> help;
  for (const auto& words : commands) {
    ASSERT_GE(words.size(), 2u);
    const std::string& sub = words[1];
    if (!help.contains(sub)) help[sub] = run_in(work_dir(), sub + " --help").out;
    for (const auto& word : words) {
      EXPECT_EQ(word.find_first_of("[]"), std::string::npos) << "brackets in README's command: " << word;
      if (word.rfind("--", 0) != 0) continue;
      const std::string option = word.substr(0, word.find('='));
      EXPECT_NE(help[sub].find(option), std::string::npos) << "airlight " << sub << " has no " << option;
    }
  }
}

// The quick ones (list, render, compare) run from a fresh directory as printed,
// with the repository's examples beside them.
TEST(Readme, QuickCommandsRunAsPrinted) {
  const fs::path dir = work_dir() / "readme_run";
  fs::create_directories(dir / "out");
  fs::create_directory_symlink(source_dir() / "examples", dir / "examples");
  int ran = 0;
  for (const auto& words : readme_commands()) {
    if (words[1] != "list" && words[1] != "render" && words[1] != "compare") continue;
    std::string args;
    for (size_t i = 1; i < words.size(); ++i) args += " '" + words[i] + "'";
    const Outcome o = run_in(dir, args, "AIRLIGHT_CACHE=" + (dir / "cache").string());
    EXPECT_EQ(o.status, 0) << "airlight" << args << "\n" << o.err;
    ++ran;
  }
  EXPECT_GE(ran, 4);
}

// Each message README quotes, reproduced by the input it describes.
struct Example {
  std::map<std::string, std::string> files;  // written into the run's directory first
  std::string args;
};

const std::map<std::string, Example>& examples() {
  static const std::map<std::string, Example> all = {
      {"airlight: error: scenes/x.json: lights[1].cone_deg: must be in (0, 180], got 200",
       {{{"scenes/x.json",
          R"({"format": "airlight-scene/1", "lights": [{"type": "point", "position": [0, 1, 0], "intensity": 1},
              {"type": "spot", "position": [0, 2, 0], "direction": [0, -1, 0], "intensity": 1, "cone_deg": 200}]})"}},
        "render --scene scenes/x.json --out x.png"}},
      {"airlight: error: --size: 16384x16384: needs about 40.0 GiB of memory (raymarch: 160 bytes per pixel), more "
       "than the 21.5 GiB available",
       {{}, "render --builtin teapot_spot --method raymarch --size 16384x16384 --out x.png"}},
      {"airlight: error: --set: volume_resolution=4096: light_volume needs about 8.5 GiB of memory, 8.4 GiB of it for "
       "the light volume meshes of 1 spot map (6·4096² triangles and the sides), 80 bytes a triangle, more than the "
       "1.0 GiB available",
       {{},
        "render --builtin teapot_spot --method light_volume --set shadow_resolution=4096 --set volume_resolution=4096 "
        "--out x.png"}},
      {"airlight: error: --set: max_triangles=1000: the scene teapot_spot has 4300 caster triangles summed over its "
       "lights, more than beam_volumes takes at this setting (each light's beam tree holds every caster triangle and is "
       "built on the CPU every frame); a larger max_triangles renders it anyway",
       {{}, "render --builtin teapot_spot --method beam_volumes --set max_triangles=1000 --out x.png"}},
      {"airlight: error: --sweep: steps: must be in [1, 4096], got 0",
       {{}, "bench --builtin teapot_spot --methods raymarch --sweep raymarch.steps=4,0 --csv b.csv"}},
      {"airlight: error: --equal-quality: --csv -: its table is written beside the CSV file, as "
       "FILE-equal-quality.csv, and standard output is no file: give --csv FILE",
       {{}, "bench --builtin teapot_spot --methods raymarch --csv - --equal-quality 0.05"}},
      {"airlight: warning: mesh.obj: skipped 3 degenerate triangles (zero area)",
       {{{"mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
                      "f 1 1 2\nf 2 3 3\nf 4 4 4\n"},
         {"x.json", R"({"format": "airlight-scene/1", "objects": [{"mesh": "mesh.obj"}]})"}},
        "render --scene x.json --size 8x6 --out x.pfm"}},
      {"airlight: error: --out: out/x/a.png: no such directory: out/x",
       {{}, "render --builtin teapot_spot --out out/x/a.png"}},
  };
  return all;
}

// The memory README's message says was available, given to the run, so that
// the machine's own does not change the message.
std::string memory_env(const std::string& message) {
  const size_t end = message.rfind(" GiB available"), start = message.rfind(' ', end - 1) + 1;
  const double gib = std::stod(message.substr(start, end - start));
  return "AIRLIGHT_MEMORY_MIB=" + std::to_string(static_cast<long>(gib * 1024.0));
}

TEST(Readme, ExampleMessagesAreTheRealOnes) {
  const std::regex quoted("`(airlight: (error|warning): [^`]*)`");
  std::set<std::string> seen;
  for (std::sregex_iterator it(readme.begin(), readme.end(), quoted), end; it != end; ++it) {
    const std::string message = (*it)[1];
    seen.insert(message);
    const auto example = examples().find(message);
    if (example == examples().end()) {
      ADD_FAILURE() << "README quotes a message this test cannot reproduce: " << message;
      continue;
    }
    const fs::path dir = work_dir() / ("message_" + std::to_string(seen.size()));
    const std::string env = message.find("GiB available") != std::string::npos ? memory_env(message) : "";
    for (const auto& [name, text] : example->second.files) {
      fs::create_directories((dir / name).parent_path());
      std::ofstream(dir / name) << text;
    }
    fs::create_directories(dir);
    const Outcome o = run_in(dir, example->second.args, env);
    EXPECT_NE(o.err.find(message + "\n"), std::string::npos) << "README: " << message << "\nreal: " << o.err;
  }
  EXPECT_EQ(seen.size(), examples().size()) << "an example here that README no longer quotes";
}

}  // namespace
}  // namespace airlight
