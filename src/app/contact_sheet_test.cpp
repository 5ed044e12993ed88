// The contact sheet's heat map scale (issue 15): a percentile, so that one
// outlier does not flatten every other error to black.
#include "app/contact_sheet.hpp"

#include <gtest/gtest.h>

namespace airlight::app {
namespace {

// A reference and a method whose error at pixel i is (i + 1)·1e-3 W/(m²·sr) in one
// channel, except the last pixel: an outlier of 1000.
struct Errors {
  Image reference{20, 10, glm::vec3(0.5f)}, method = reference;
  Errors() {
    for (size_t i = 0; i < method.pixels.size(); ++i) method.pixels[i].g += 1e-3f * float(i + 1);
    method.pixels.back().r += 1000.0f;
  }
  std::vector<SheetEntry> entries() const {
    return {{"reference", "", "", 0.0, 0.0, &reference}, {"method", "", "", 0.0, 0.0, &method}};
  }
};

TEST(ContactSheet, HeatScaleIsThe99thPercentileNotTheOutlier) {
  const Errors e;
  const HeatScale scale = heat_scale(e.entries());
  // 200 nonzero errors: the nearest rank ceil(0.99·200) = 198 is 0.198 (float
  // sums around 0.5 are good to 1e-7).
  EXPECT_NEAR(scale.top, 0.198, 1e-6);
  EXPECT_NEAR(scale.largest, 1000.0, 1e-3);
  EXPECT_EQ(describe(scale),
            "scale 0 to 0.198 W/(m^2 sr): the 99th percentile of the nonzero errors; "
            "larger ones, up to 1e+03, saturate");
}

TEST(ContactSheet, ExactPixelsAndTheReferenceColumnDoNotLowerTheScale) {
  Errors e;
  const Image exact = e.reference;
  // Half the image exact: the percentile is taken over the 100 pixels with an error.
  for (size_t i = 0; i < 100; ++i) e.method.pixels[i] = e.reference.pixels[i];
  auto entries = e.entries();
  entries.push_back({"reference", "", "", 0.0, 0.0, &exact});
  // ceil(0.99·100) = 99th of the errors 0.101 … 0.200 (outlier): 0.199.
  EXPECT_NEAR(heat_scale(entries).top, 0.199, 1e-6);
  EXPECT_EQ(heat_scale({entries[0], entries[2]}).top, 1.0);  // all exact: a finite scale all the same
}

}  // namespace
}  // namespace airlight::app
