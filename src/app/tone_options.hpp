#pragma once
// --tonemap and --exposure for PNG output, shared by render and compare
// (docs/decisions.md "PNG tone mapping").
#include "core/tonemap.hpp"

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace airlight::app {

// "auto" (nullopt) or a positive finite number; throws InputError naming
// --exposure for anything else.
std::optional<float> parse_exposure(const std::string& text);

struct ToneOptions {
  std::string curve = "agx";
  std::optional<float> exposure = 1.0f;  // nullopt: auto

  void add_options(CLI::App& command);
  // The tone map for `image`; with --exposure auto the exposure is measured on
  // it and printed to stderr after "<command>: ".
  ToneMap resolve(const Image& image, const std::string& command) const;
};

}  // namespace airlight::app
