#include "core/warning.hpp"

#include <iostream>

namespace airlight {

namespace {
std::ostream* stream = nullptr;
}  // namespace

void warn(const std::string& file, const std::string& message) {
  (stream ? *stream : std::cerr) << "airlight: warning: " << file << ": " << message << "\n";
}

std::ostream* set_warning_stream(std::ostream* out) {
  std::ostream* previous = stream;
  stream = out;
  return previous;
}

}  // namespace airlight
