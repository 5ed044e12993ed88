#pragma once
// End-to-end tests of the `airlight` executable (test::airlight_exe()): a work
// directory per test process (removed when it ends), a run's exit status,
// stdout and stderr, CSV output, and the bad-input check of docs/design.md §5 — exit 2
// with a message "airlight: error: <file or option>: <key>: ...".
#include "core/test_paths.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace airlight::test {

namespace fs = std::filesystem;

inline const fs::path& work_dir() {
  static const struct Dir {
    fs::path path = fs::temp_directory_path() / ("airlight_command_test_" + std::to_string(::getpid()));
    Dir() {
      fs::remove_all(path);
      fs::create_directories(path);
    }
    ~Dir() { fs::remove_all(path); }
  } dir;
  return dir.path;
}

inline std::string read_text(const fs::path& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

inline fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path file = work_dir() / name;
  std::ofstream(file) << text;
  return file;
}

struct Outcome {
  int status = -1;
  std::string out, err;
};

// Runs `airlight ARGS` with `env` ("NAME=value ..." or empty) in its environment.
inline Outcome run_airlight(const std::string& args, const std::string& env = "") {
  const fs::path out = work_dir() / "stdout.txt", err = work_dir() / "stderr.txt";
  const std::string command = (env.empty() ? "" : "env " + env + " ") + airlight_exe().string() + " " + args +
                              " >" + out.string() + " 2>" + err.string();
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_text(out), read_text(err)};
}

// The methods `airlight list methods` names, `reference` among them unless left out.
inline std::vector<std::string> listed_methods(bool with_reference = true) {
  const Outcome o = run_airlight("list methods");
  std::vector<std::string> names;
  std::stringstream lines(o.out);
  for (std::string line; std::getline(lines, line);) {
    const size_t end = line.find_first_of(" \t");
    const std::string name = line.substr(0, end);
    if (!name.empty() && end != std::string::npos && (with_reference || name != "reference")) names.push_back(name);
  }
  return names;
}

// Exit 2 and a message starting "airlight: error: <where>: <key>: " (no key: "<where>: ").
inline void expect_bad_input(const Outcome& o, const std::string& where, const std::string& key,
                             const std::string& context) {
  EXPECT_EQ(o.status, 2) << context << "\n" << o.err;
  const std::string prefix = "airlight: error: " + where + (key.empty() ? "" : ": " + key) + ": ";
  EXPECT_EQ(o.err.rfind(prefix, 0), 0u) << "expected a message starting with '" << prefix << "', got: " << o.err;
}

using Table = std::vector<std::vector<std::string>>;

// Comma-separated cells (the fields here hold no commas or quotes).
inline Table parse_csv(const std::string& text) {
  Table table;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(cell);
    if (!line.empty() && line.back() == ',') row.push_back("");
    table.push_back(row);
  }
  return table;
}

inline Table read_csv(const fs::path& file) { return parse_csv(read_text(file)); }

// `table` without the columns `varies` names: those a rerun changes (times, memory).
template <typename Predicate>
Table without_columns(const Table& table, Predicate varies) {
  Table kept(table.size());
  for (size_t i = 0; i < table.size(); ++i)
    for (size_t c = 0; c < table[i].size(); ++c)
      if (c >= table[0].size() || !varies(table[0][c])) kept[i].push_back(table[i][c]);
  return kept;
}

inline size_t column(const Table& table, const std::string& name) {
  const auto& header = table.at(0);
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << "no column " << name;
  return static_cast<size_t>(it - header.begin());
}

}  // namespace airlight::test
