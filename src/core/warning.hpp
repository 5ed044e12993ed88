#pragma once
// Warnings: input that is used, but not quite as written (docs/design.md §5).
#include <iosfwd>
#include <sstream>
#include <string>

namespace airlight {

// Writes "airlight: warning: <file>: <message>" on a line of its own to stderr,
// or to the stream set_warning_stream chose.
void warn(const std::string& file, const std::string& message);

// Sends warnings to `out` (nullptr: stderr again); returns the previous stream.
// For tests that check what a load warns.
std::ostream* set_warning_stream(std::ostream* out);

// The warnings written while it lives, for tests that check what a call warns.
class CapturedWarnings {
public:
  CapturedWarnings() : previous_(set_warning_stream(&text_)) {}
  ~CapturedWarnings() { set_warning_stream(previous_); }
  CapturedWarnings(const CapturedWarnings&) = delete;
  CapturedWarnings& operator=(const CapturedWarnings&) = delete;
  std::string text() const { return text_.str(); }

private:
  std::ostringstream text_;
  std::ostream* previous_;
};

}  // namespace airlight
