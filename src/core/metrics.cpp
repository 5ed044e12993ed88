#include "core/metrics.hpp"

#include "core/image_io.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace airlight {

namespace {
// The 8-bit code PNG output would store for a linear value.
double png_code(float linear, float exposure) { return std::round(255.0 * linear_to_srgb(linear * exposure)); }
}  // namespace

ImageError compare_images(const Image& method, const Image& reference, float exposure) {
  if (method.width != reference.width || method.height != reference.height)
    throw std::invalid_argument("images of different sizes cannot be compared");
  double squared = 0.0, sum = 0.0, max_abs = 0.0, tone_squared = 0.0;
  for (size_t i = 0; i < reference.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double m = method.pixels[i][c], r = reference.pixels[i][c];
      squared += (m - r) * (m - r);
      sum += r;
      max_abs = std::max(max_abs, std::abs(m - r));
      const double t = png_code(method.pixels[i][c], exposure) - png_code(reference.pixels[i][c], exposure);
      tone_squared += t * t;
    }
  const double n = 3.0 * static_cast<double>(reference.pixels.size());
  ImageError e;
  e.mean_reference = sum / n;
  // An all-black reference has no relative scale: any error is then infinite.
  e.rel_rmse = e.mean_reference > 0.0 ? std::sqrt(squared / n) / e.mean_reference
                                      : (squared > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
  e.max_abs = max_abs;
  e.psnr_db = tone_squared > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / (tone_squared / n))
                                 : std::numeric_limits<double>::infinity();
  return e;
}

}  // namespace airlight
