#pragma once
// The methods and their settings from the command line — render's --set,
// compare's --methods and --set, bench's --methods, --set and --sweep — checked
// before anything runs. Methods are looked up with find_method.
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

// compare: one entry of --methods, "name" or "name:key=value;key=value".
struct MethodEntry {
  const MethodInfo* info = nullptr;
  Settings settings;
};

// compare's --methods (entries separated by ',') with the --set assignments, each
// "method.key=value" for a method of the list; throws InputError naming the option.
std::vector<MethodEntry> parse_entries(const std::string& methods, const std::vector<std::string>& assignments);

// bench: one method with one choice of settings, a point of the plot.
struct Variant {
  const MethodInfo* method = nullptr;
  Settings settings;
  std::string series;  // its line in the plot: the method and the values of all but its last sweep
};

// bench's runs of every method of --methods, in order: its --set assignments
// ("method.key=value", or "key=value" with one method) crossed with its --sweep
// values ("method.key=v1,v2,..."); throws InputError naming the option.
std::vector<Variant> plan_variants(const std::vector<std::string>& methods, const std::vector<std::string>& sweeps,
                                   const std::vector<std::string>& assignments);

}  // namespace airlight::app
