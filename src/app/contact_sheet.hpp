#pragma once
// The contact sheet of `airlight compare` (issue 6): one column per image, the
// tone-mapped image under its label, beneath it the error heat map against the
// reference, and one colour bar for all heat maps.
#include <airlight/image.hpp>
#include <filesystem>
#include <string>
#include <vector>

namespace airlight::app {

struct SheetEntry {
  std::string method;    // e.g. "raymarch"
  std::string settings;  // e.g. "steps=16 jitter=blue"
  std::string note;      // shown after the method name, e.g. "cached"
  double seconds = 0.0;  // prepare + render
  double rel_rmse = 0.0;
  const Image* image = nullptr;  // the compared pass, same size as the reference
};

// Writes the sheet as PNG; entries[0] is the reference, whose pixels every heat
// map is measured against. Throws Failure when the file cannot be written.
void write_contact_sheet(const std::vector<SheetEntry>& entries, float exposure, const std::filesystem::path& file);

}  // namespace airlight::app
