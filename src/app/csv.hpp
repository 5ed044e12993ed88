#pragma once
// CSV output: RFC 4180 fields, and the file "-" that names standard output
// (README "Pipes"), so a CSV can feed a pipe. While the CSV goes there,
// whatever the command would print on stdout goes to stderr instead: the
// output stays one CSV a reader parses alone.
#include "app/output_check.hpp"
#include "core/atomic_file.hpp"

#include <airlight/error.hpp>

#include <cstdio>
#include <string>

namespace airlight::app {

// One CSV field as RFC 4180 writes it: quoted when it holds a comma, a quote or
// a line break, its quotes doubled. Settings and messages may hold any of them.
inline std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

inline bool is_standard_output(const std::string& file) { return file == "-"; }

// The option's CSV file can be written (check_output_file), unless it is "-".
inline void check_csv_output(const std::string& option, const std::string& file) {
  if (!is_standard_output(file)) check_output_file(option, file, {".csv"});
}

// `text` into `file` atomically, or onto standard output when `file` is "-".
inline void write_csv_output(const std::string& file, const std::string& text) {
  if (!is_standard_output(file)) return write_text_file(file, text);
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0)
    throw Failure("cannot write the CSV to standard output");
}

// Where a command prints its report: stderr while `csv` is standard output.
inline std::FILE* report_stream(const std::string& csv) { return is_standard_output(csv) ? stderr : stdout; }

}  // namespace airlight::app
