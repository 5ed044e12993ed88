#include "core/image_io.hpp"

#include <airlight/error.hpp>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
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

std::string decode_error(const std::string& bytes, const std::string& name) {
  try {
    decode_image(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  return "decoded";
}

std::string u32(std::uint32_t v, bool big_endian = false) {
  if (big_endian) v = __builtin_bswap32(v);
  return std::string(reinterpret_cast<const char*>(&v), 4);
}

// An EXR header of the given version flags and attributes ({name, type, value}).
std::string exr_header(std::uint32_t flags, const std::vector<std::array<std::string, 3>>& attributes) {
  std::string bytes = u32(20000630) + u32(2 | flags);
  for (const auto& [name, type, value] : attributes)
    bytes += name + '\0' + type + '\0' + u32(std::uint32_t(value.size())) + value;
  return bytes + '\0';
}

// PNG and EXR give their size in a header, and a few bytes can claim any size: the
// pixels are counted before anything is decoded (docs/decisions.md "Fuzzing").
TEST(ImageIo, MoreThan4096SquaredPixelsAreRefusedBeforeDecoding) {
  const std::string ihdr = u32(5000, true) + u32(4000, true) + std::string("\x08\x02\0\0\0", 5);
  const std::string png = std::string("\x89PNG\r\n\x1a\n") + u32(13, true) + "IHDR" + ihdr + u32(0) + u32(0) + "IEND" + u32(0);
  const std::string message = "the image is 5000x4000 pixels, more than the 16777216 (4096x4096) airlight reads";
  EXPECT_EQ(decode_error(png, "big.png"), "big.png: " + message);
  const std::string window = u32(0) + u32(0) + u32(4999) + u32(3999);
  EXPECT_EQ(decode_error(exr_header(0, {{"dataWindow", "box2i", window}}), "big.exr"),
            "big.exr: " + message);
}

TEST(ImageIo, PfmDataShorterThanItsHeaderSaysIsRefusedBeforeAllocating) {
  EXPECT_EQ(decode_error("PF\n65536 65536\n-1.0\n" + std::string(12, '\0'), "huge.pfm"), "huge.pfm: PFM data ends early");
}

// OpenEXR allocates what a header states before reading it; what it cannot read is
// refused first.
TEST(ImageIo, ExrHeadersAreCheckedBeforeOpenExrReadsThem) {
  EXPECT_EQ(decode_error(exr_header(0x200, {}), "t.exr"),
            "t.exr: cannot read EXR: a tiled, deep or multi-part file: airlight reads single-part scanline images");
  std::string past_end = exr_header(0, {{"comment", "string", "abc"}});
  past_end[past_end.size() - 9] = '\x7f';  // its size: 0x7f000003 bytes
  EXPECT_EQ(decode_error(past_end, "p.exr"),
            "p.exr: cannot read EXR: the header's attribute \"comment\" runs past the end of the file");
  EXPECT_EQ(decode_error(exr_header(0, {{"dataWindow", "box2i", std::string(12, '\0')}}), "w.exr"),
            "w.exr: cannot read EXR: the header's attribute \"dataWindow\" is not a well-formed box2i");
  EXPECT_EQ(decode_error(exr_header(0, {{std::string(32, 'n'), "int", u32(1)}}), "n.exr"),
            "n.exr: cannot read EXR: the header has a name longer than 31 characters");
}

// A data window need not start at (0, 0): the pixels land in the image all the same.
TEST(ImageIo, ExrDataWindowAwayFromTheOriginIsRead) {
  const Image image = gradient(7, 5);
  const fs::path file = temp_file("window.exr");
  write_image(image, file);
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  // The header's attributes, then the offset of the one line block (5 lines, ZIP's 16
  // a block), which starts with its first line's y.
  size_t at = 8, window = 0;
  while (bytes[at] != '\0') {
    const size_t type = bytes.find('\0', at) + 1, value = bytes.find('\0', type) + 5;
    if (bytes.compare(at, type - at, std::string("dataWindow", 11)) == 0) window = value;
    std::uint32_t size = 0;
    std::memcpy(&size, bytes.data() + value - 4, 4);
    at = value + size;
  }
  std::uint64_t block = 0;
  std::memcpy(&block, bytes.data() + at + 1, 8);
  // The window and the block's y moved by (-3, -2).
  const std::int32_t moved[4] = {-3, -2, 3, 2}, y = -2;
  std::memcpy(bytes.data() + window, moved, sizeof moved);
  std::memcpy(bytes.data() + block, &y, 4);
  const Image back = decode_image(bytes, file);
  ASSERT_EQ(back.width, 7);
  ASSERT_EQ(back.height, 5);
  for (size_t i = 0; i < image.pixels.size(); ++i) EXPECT_EQ(back.pixels[i], image.pixels[i]) << i;
}

TEST(ImageIo, UnknownOutputExtensionIsAnInputError) {
  EXPECT_THROW(write_image(Image(1, 1), temp_file("x.jpg")), InputError);
}

}  // namespace
}  // namespace airlight
