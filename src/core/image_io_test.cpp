#include "core/image_io.hpp"

#include <airlight/error.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>

namespace airlight {
namespace {

namespace fs = std::filesystem;

fs::path temp_file(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "airlight_core_test";
  fs::create_directories(dir);
  return dir / name;
}

Image gradient(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.at(x, y) = {0.1f * x, 0.01f * y + 0.5f, 1.0f / (1 + x + y)};
  return image;
}

TEST(ImageIo, FloatFormatsRoundTripExactly) {
  const Image image = gradient(7, 5);
  for (const char* name : {"g.pfm", "g.exr"}) {
    const fs::path file = temp_file(name);
    write_image(image, file);
    const Image back = read_image(file);
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    for (size_t i = 0; i < image.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], image.pixels[i]) << name << " " << i;
  }
}

TEST(ImageIo, PfmStoresTheBottomRowFirstLittleEndian) {
  Image image(1, 2);
  image.at(0, 0) = glm::vec3(1.0f);  // top row
  image.at(0, 1) = glm::vec3(2.0f);  // bottom row
  const fs::path file = temp_file("rows.pfm");
  write_image(image, file);
  std::ifstream in(file, std::ios::binary);
  std::string header((std::istreambuf_iterator<char>(in)), {});
  ASSERT_EQ(header.substr(0, 12), "PF\n1 2\n-1.0\n");
  float first = 0;
  std::memcpy(&first, header.data() + 12, 4);
  EXPECT_EQ(first, 2.0f);  // the bottom row comes first
}

TEST(ImageIo, PngRoundTripsWithinOneSrgbStep) {
  Image image(3, 1);
  image.at(0, 0) = glm::vec3(0.0f);
  image.at(1, 0) = glm::vec3(0.214f);  // ≈ sRGB 0.5
  image.at(2, 0) = glm::vec3(5.0f);    // over-exposed: clamps to 1
  const fs::path file = temp_file("t.png");
  write_image(image, file, ToneMap{1.0f, ToneCurve::clamp});  // radiance as sRGB, no curve
  const Image back = read_image(file);
  // 8-bit sRGB: half a code step at 0.5 is ≈ 0.002 in linear terms.
  EXPECT_NEAR(back.at(1, 0).r, 0.214f, 0.003f);
  EXPECT_EQ(back.at(0, 0).g, 0.0f);
  EXPECT_EQ(back.at(2, 0).b, 1.0f);
}

TEST(ImageIo, ExposureScalesBeforeEncoding) {
  Image image(1, 1, glm::vec3(0.1f));
  const fs::path file = temp_file("e.png");
  write_image(image, file, ToneMap{2.0f, ToneCurve::clamp});
  EXPECT_NEAR(read_image(file).at(0, 0).r, 0.2f, 0.003f);  // one 8-bit sRGB step near 0.2
}

TEST(ImageIo, NonFiniteValuesNeverReachAFile) {
  Image image(2, 1);
  image.at(0, 0) = glm::vec3(std::numeric_limits<float>::quiet_NaN());
  image.at(1, 0) = glm::vec3(std::numeric_limits<float>::infinity());
  const fs::path file = temp_file("nan.pfm");
  write_image(image, file);
  const Image back = read_image(file);
  EXPECT_EQ(back.at(0, 0).r, 0.0f);
  EXPECT_TRUE(std::isfinite(back.at(1, 0).r));
}

TEST(ImageIo, SrgbTransferFunctionsAreInverse) {
  for (float v = 0.0f; v <= 1.0f; v += 0.01f) EXPECT_NEAR(srgb_to_linear(linear_to_srgb(v)), v, 1e-5f);
  EXPECT_NEAR(linear_to_srgb(0.5f), 0.7354f, 1e-4f);  // IEC 61966-2-1 value
}

void expect_input_error(const fs::path& file, const std::string& fragment) {
  try {
    read_image(file);
    FAIL() << "expected InputError for " << file;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string());
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(ImageIo, BadFilesAreInputErrorsNamingTheFile) {
  expect_input_error(temp_file("missing.png"), "no such file");
  const fs::path junk = temp_file("junk.pfm");
  std::ofstream(junk) << "P6 nonsense";
  expect_input_error(junk, "not an RGB PFM");
  const fs::path short_pfm = temp_file("short.pfm");
  std::ofstream(short_pfm, std::ios::binary) << "PF\n4 4\n-1.0\n1234";
  expect_input_error(short_pfm, "ends early");
  const fs::path bad_png = temp_file("bad.png");
  std::ofstream(bad_png) << "not a png";
  expect_input_error(bad_png, "not a PNG image (the file is damaged or another format)");
  const fs::path bad_ext = temp_file("x.bmp");
  std::ofstream(bad_ext) << "x";
  expect_input_error(bad_ext, "unknown image format");
}

TEST(ImageIo, UnknownOutputExtensionIsAnInputError) {
  EXPECT_THROW(write_image(Image(1, 1), temp_file("x.jpg")), InputError);
}

}  // namespace
}  // namespace airlight
