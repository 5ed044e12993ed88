#pragma once
// How far an image is from the reference (docs/design.md §6): relative RMSE =
// sqrt(mean((m − r)²)) / mean(r) over all pixels and channels, the maximum
// absolute error, and the PSNR of the tone-mapped (8-bit sRGB) images.
#include <airlight/image.hpp>

namespace airlight {

struct ImageError {
  double rel_rmse = 0.0;
  double max_abs = 0.0;
  double psnr_db = 0.0;       // of the tone-mapped images; +inf when identical
  double mean_reference = 0.0;
};

// Throws std::invalid_argument when the sizes differ.
ImageError compare_images(const Image& method, const Image& reference, float exposure = 1.0f);

}  // namespace airlight
