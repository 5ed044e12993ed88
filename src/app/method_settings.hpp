#pragma once
// A method's settings from the command line's assignments, shared by render,
// compare and bench.
#include <airlight/method.hpp>
#include <string>
#include <vector>

namespace airlight::app {

// "key=value" or "method.key=value" (the form bench sweeps use) for each
// assignment; throws InputError("--set", key) for an unknown key, a bad value,
// or a key naming another method.
Settings method_settings(const MethodInfo& method, const std::vector<std::string>& assignments);

// The parts of `text` between separators, empty ones included ("a,,b" → a, "", b).
std::vector<std::string> split(const std::string& text, char separator);

}  // namespace airlight::app
