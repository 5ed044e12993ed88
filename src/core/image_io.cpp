#include "core/image_io.hpp"

#include "core/atomic_file.hpp"
#include "core/file_source.hpp"

#include <airlight/error.hpp>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

namespace airlight {

namespace fs = std::filesystem;

float linear_to_srgb(float linear) {
  const float c = std::clamp(linear, 0.0f, 1.0f);
  return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

float srgb_to_linear(float encoded) {
  const float c = std::clamp(encoded, 0.0f, 1.0f);
  return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

namespace {

std::string extension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

[[noreturn]] void unreadable(const fs::path& file, const std::string& why) {
  throw InputError(file.string(), "", why);
}

// A non-finite value never reaches a file: NaN becomes 0, ±Inf the largest float.
float finite(float v) {
  if (std::isnan(v)) return 0.0f;
  return std::clamp(v, -3.4e38f, 3.4e38f);
}

void write_png(const Image& image, const fs::path& file, const ToneMap& tone) {
  std::vector<std::uint8_t> bytes(image.pixels.size() * 3);
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    const glm::vec3 encoded = tone_map(image.pixels[i], tone);  // finite, in [0, 1]
    for (int c = 0; c < 3; ++c) bytes[3 * i + c] = static_cast<std::uint8_t>(std::lround(255.0f * encoded[c]));
  }
  if (!stbi_write_png(file.c_str(), image.width, image.height, 3, bytes.data(), image.width * 3))
    throw Failure("cannot write " + file.string());
}

// PFM: "PF\n<w> <h>\n<-1.0>\n" then float RGB rows, bottom row first, little-endian.
void write_pfm(const Image& image, const fs::path& file) {
  std::ofstream out(file, std::ios::binary);
  if (!out) throw Failure("cannot write " + file.string());
  out << "PF\n" << image.width << ' ' << image.height << "\n-1.0\n";
  std::vector<float> row(static_cast<size_t>(image.width) * 3);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) row[3 * x + c] = finite(image.at(x, y)[c]);
    out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size() * 4));
  }
  if (!out) throw Failure("cannot write " + file.string());
}

// The data must hold every pixel the header announces before any is allocated.
Image read_pfm(const std::string& bytes, const fs::path& file) {
  std::istringstream in(bytes);
  std::string magic;
  int width = 0, height = 0;
  double scale = 0;
  if (!(in >> magic >> width >> height >> scale) || magic != "PF" || width <= 0 || height <= 0 ||
      width > 65536 || height > 65536 || scale == 0 || !std::isfinite(scale))
    unreadable(file, "not an RGB PFM file (expected \"PF\", width, height, scale)");
  in.get();  // the single whitespace byte after the scale
  const size_t row_bytes = static_cast<size_t>(width) * 3 * 4;
  const auto start = static_cast<size_t>(in.tellg());
  if (in.eof() || (bytes.size() - start) / row_bytes < static_cast<size_t>(height))
    unreadable(file, "PFM data ends early");
  const bool big_endian = scale > 0;
  Image image(width, height);
  for (int y = height - 1; y >= 0; --y) {
    const char* row = bytes.data() + start + static_cast<size_t>(height - 1 - y) * row_bytes;
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        std::uint32_t bits;
        std::memcpy(&bits, row + 4 * (3 * x + c), 4);
        if (big_endian) bits = __builtin_bswap32(bits);
        image.at(x, y)[c] = std::bit_cast<float>(bits);
      }
  }
  return image;
}

// PNG and EXR data are compressed: their size does not bound their pixels, which the
// header gives; a gobo needs far fewer (docs/decisions.md "Fuzzing").
constexpr long long max_decoded_pixels = 4096LL * 4096;

void check_pixels(long long width, long long height, const fs::path& file) {
  if (width * height > max_decoded_pixels)
    unreadable(file, "the image is " + std::to_string(width) + "x" + std::to_string(height) +
                         " pixels, more than the " + std::to_string(max_decoded_pixels) + " (4096x4096) airlight reads");
}

// stb_image's failure reason in plain words; the rarer ones, all some damage to
// the PNG data, keep stb's code for whoever digs further.
std::string png_failure(const std::string& reason) {
  static const std::map<std::string, std::string> plain = {
      {"unknown image type", "not a PNG image (the file is damaged or another format)"},
      {"outofdata", "the file is cut short"},
      {"can't fopen", "cannot open the file"},
      {"outofmem", "not enough memory to decode it"},
      {"too large", "the image is too large to decode"}};
  const auto it = plain.find(reason);
  return it != plain.end() ? it->second : "the PNG data is damaged (stb_image: " + reason + ")";
}

// PNG only: stb_image would decode a dozen other formats behind a .png name.
Image read_png(const std::string& bytes, const fs::path& file) {
  static constexpr std::string_view signature = "\x89PNG\r\n\x1a\n";
  if (!bytes.starts_with(signature)) unreadable(file, png_failure("unknown image type"));
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  const int size = static_cast<int>(std::min<size_t>(bytes.size(), INT_MAX));
  int width = 0, height = 0, channels = 0;
  if (!stbi_info_from_memory(data, size, &width, &height, &channels)) unreadable(file, png_failure(stbi_failure_reason()));
  check_pixels(width, height, file);
  std::uint8_t* pixels = stbi_load_from_memory(data, size, &width, &height, &channels, 3);
  if (!pixels) unreadable(file, png_failure(stbi_failure_reason()));
  Image image(width, height);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) image.pixels[i][c] = srgb_to_linear(pixels[3 * i + c] / 255.0f);
  stbi_image_free(pixels);
  return image;
}

constexpr std::array<const char*, 3> exr_channels{"R", "G", "B"};

void write_exr(const Image& image, const fs::path& file) {
  Image clean = image;
  for (auto& p : clean.pixels) p = glm::vec3(finite(p.r), finite(p.g), finite(p.b));
  try {
    Imf::Header header(image.width, image.height);
    Imf::FrameBuffer frame;
    for (int c = 0; c < 3; ++c) {
      header.channels().insert(exr_channels[c], Imf::Channel(Imf::FLOAT));
      frame.insert(exr_channels[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&clean.pixels[0][c]),
                                               sizeof(glm::vec3), sizeof(glm::vec3) * image.width));
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
  } catch (const std::exception& e) {
    throw Failure("cannot write " + file.string() + ": " + e.what());
  }
}

// OpenEXR reads through this from the bytes in memory.
class MemoryStream : public Imf::IStream {
public:
  MemoryStream(const std::string& bytes, const fs::path& file) : Imf::IStream(file.c_str()), bytes_(bytes) {}

  bool read(char c[], int n) override {
    if (n < 0 || static_cast<size_t>(n) > bytes_.size() - position_) throw std::runtime_error("the file is cut short");
    std::memcpy(c, bytes_.data() + position_, static_cast<size_t>(n));
    position_ += static_cast<size_t>(n);
    return position_ < bytes_.size();
  }
  std::uint64_t tellg() override { return position_; }
  void seekg(std::uint64_t position) override { position_ = std::min<std::uint64_t>(position, bytes_.size()); }

private:
  const std::string& bytes_;
  size_t position_ = 0;
};

Image read_exr(const std::string& bytes, const fs::path& file) {
  // OpenEXR sizes its tables from the header as it opens the file: the header is refused
  // first when a side exceeds a render's largest (16384), then by the pixel count.
  static const bool bounded = (Imf::Header::setMaxImageSize(16384, 16384), Imf::Header::setMaxTileSize(16384, 16384), true);
  (void)bounded;
  try {
    MemoryStream stream(bytes, file);
    Imf::InputFile in(stream);
    const auto window = in.header().dataWindow();
    const long long width = 1LL + window.max.x - window.min.x, height = 1LL + window.max.y - window.min.y;
    check_pixels(width, height, file);
    Image image(static_cast<int>(width), static_cast<int>(height));
    Imf::FrameBuffer frame;
    char* origin = reinterpret_cast<char*>(image.pixels.data()) -
                   (static_cast<std::ptrdiff_t>(window.min.y) * width + window.min.x) * sizeof(glm::vec3);
    for (int c = 0; c < 3; ++c)
      frame.insert(exr_channels[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), sizeof(glm::vec3),
                                               sizeof(glm::vec3) * width, 1, 1, 0.0));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    unreadable(file, std::string("cannot read EXR: ") + e.what());
  }
}

}  // namespace

void write_image(const Image& image, const fs::path& file, const ToneMap& tone) {
  const std::string ext = extension(file);
  if (ext != ".png" && ext != ".pfm" && ext != ".exr")
    throw InputError(file.string(), "", "unknown image format '" + ext + "' (use .png, .pfm or .exr)");
  write_atomically(file, [&](const fs::path& temp) {
    if (ext == ".png") return write_png(image, temp, tone);
    if (ext == ".pfm") return write_pfm(image, temp);
    write_exr(image, temp);
  });
}

Image decode_image(const std::string& bytes, const fs::path& file) {
  const std::string ext = extension(file);
  if (ext == ".png") return read_png(bytes, file);
  if (ext == ".pfm") return read_pfm(bytes, file);
  if (ext == ".exr") return read_exr(bytes, file);
  throw InputError(file.string(), "", "unknown image format '" + ext + "' (use .png, .pfm or .exr)");
}

Image read_image(const fs::path& file) {
  if (!fs::is_regular_file(file)) throw InputError(file.string(), "", "no such file");
  return decode_image(disk_files().read(file), file);
}

}  // namespace airlight
