#pragma once
// What each fuzz target feeds its input to (docs/decisions.md "Fuzzing"): the
// command's loaders and option parsers, reading from memory. An input's outcome is
// empty when it is accepted and the error's text when it is refused (InputError or
// Failure); any other exception leaves the function, which libFuzzer reports as a
// crash. The fuzz targets (fuzz_target.cpp) and the release build's replay of
// the regressions (regressions_test.cpp) call the same functions.
#include <string>

namespace airlight::fuzz {

// `name` is a target of fuzz/targets.txt; nullptr for an unknown one.
using Outcome = std::string (*)(const std::string& bytes);
Outcome target(const std::string& name);

}  // namespace airlight::fuzz
