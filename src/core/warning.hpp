#pragma once
// Warnings: input that is used, but not quite as written (docs/design.md §5).
#include <iosfwd>
#include <string>

namespace airlight {

// Writes "airlight: warning: <file>: <message>" on a line of its own to stderr,
// or to the stream set_warning_stream chose.
void warn(const std::string& file, const std::string& message);

// Sends warnings to `out` (nullptr: stderr again); returns the previous stream.
// For tests that check what a load warns.
std::ostream* set_warning_stream(std::ostream* out);

}  // namespace airlight
