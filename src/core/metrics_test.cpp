#include "core/metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace airlight {
namespace {

TEST(Metrics, RelativeRmseMaxAndPsnrOnAKnownPair) {
  Image reference(2, 1, glm::vec3(1.0f)), method(2, 1, glm::vec3(1.0f));
  method.at(1, 0) = glm::vec3(1.0f, 1.0f, 0.5f);  // one channel of six off by 0.5
  const ImageError e = compare_images(method, reference);
  EXPECT_DOUBLE_EQ(e.mean_reference, 1.0);
  EXPECT_DOUBLE_EQ(e.rel_rmse, std::sqrt(0.25 / 6.0));
  EXPECT_DOUBLE_EQ(e.max_abs, 0.5);
  // 1.0 → code 255, 0.5 → sRGB 0.7354 → code 188: PSNR = 10 log10(255² / (67² / 6)).
  EXPECT_NEAR(e.psnr_db, 10.0 * std::log10(255.0 * 255.0 / (67.0 * 67.0 / 6.0)), 1e-9);
}

TEST(Metrics, IdenticalImagesHaveNoError) {
  const Image a(3, 2, glm::vec3(0.25f));
  const ImageError e = compare_images(a, a);
  EXPECT_EQ(e.rel_rmse, 0.0);
  EXPECT_EQ(e.max_abs, 0.0);
  EXPECT_TRUE(std::isinf(e.psnr_db));
}

TEST(Metrics, BlackReferenceMakesAnyErrorInfinite) {
  const Image black(1, 1), grey(1, 1, glm::vec3(0.1f));
  EXPECT_TRUE(std::isinf(compare_images(grey, black).rel_rmse));
  EXPECT_THROW(compare_images(Image(1, 2), black), std::invalid_argument);
}

}  // namespace
}  // namespace airlight
