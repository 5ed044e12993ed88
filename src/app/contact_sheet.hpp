#pragma once
// The contact sheet of `airlight compare` (issue 6): one column per image, the
// tone-mapped image under its label, beneath it the error heat map against the
// reference, and one colour bar for all heat maps.
#include "core/tonemap.hpp"

#include <airlight/image.hpp>
#include <glm/vec3.hpp>
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

// The heat maps' common colour scale: 0 to `top`, the 99th percentile (nearest
// rank) of the nonzero errors |image − reference| (largest over RGB) of every
// entry after the reference, so that a few outliers do not flatten it; larger
// errors saturate. Zero errors are left out: pixels every method gets exactly
// right (e.g. outside the light's cone) would otherwise pull the scale to 0.
struct HeatScale {
  double top = 1.0;      // 1 when every error is 0
  double largest = 0.0;  // the largest error, shown saturated
};
HeatScale heat_scale(const std::vector<SheetEntry>& entries);

// The scale in words, as compare prints it and the sheet shows it under its bar.
std::string describe(const HeatScale& scale);

// Inferno (matplotlib) at t in [0, 1], sampled at nine points: perceptually
// uniform and still ordered when printed in grey. The heat maps' colours.
glm::dvec3 inferno(double t);

// Writes the sheet as PNG; entries[0] is the reference, whose pixels every heat
// map is measured against. Throws Failure when the file cannot be written.
void write_contact_sheet(const std::vector<SheetEntry>& entries, const HeatScale& scale, const ToneMap& tone,
                         const std::filesystem::path& file);

}  // namespace airlight::app
