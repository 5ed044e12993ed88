#pragma once
// One CSV field as RFC 4180 writes it: quoted when it holds a comma, a quote or
// a line break, its quotes doubled. Settings and messages may hold any of them.
#include <string>

namespace airlight::app {

inline std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace airlight::app
