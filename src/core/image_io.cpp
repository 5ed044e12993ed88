#include "core/image_io.hpp"

#include "core/atomic_file.hpp"

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

Image read_pfm(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string magic;
  int width = 0, height = 0;
  double scale = 0;
  if (!(in >> magic >> width >> height >> scale) || magic != "PF" || width <= 0 || height <= 0 ||
      width > 65536 || height > 65536 || scale == 0 || !std::isfinite(scale))
    unreadable(file, "not an RGB PFM file (expected \"PF\", width, height, scale)");
  in.get();  // the single whitespace byte after the scale
  const bool big_endian = scale > 0;
  Image image(width, height);
  std::vector<std::uint32_t> row(static_cast<size_t>(width) * 3);
  for (int y = height - 1; y >= 0; --y) {
    if (!in.read(reinterpret_cast<char*>(row.data()), static_cast<std::streamsize>(row.size() * 4)))
      unreadable(file, "PFM data ends early");
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c) {
        std::uint32_t bits = row[3 * x + c];
        if (big_endian) bits = __builtin_bswap32(bits);
        image.at(x, y)[c] = std::bit_cast<float>(bits);
      }
  }
  return image;
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

Image read_png(const fs::path& file) {
  int width = 0, height = 0, channels = 0;
  std::uint8_t* data = stbi_load(file.c_str(), &width, &height, &channels, 3);
  if (!data) unreadable(file, png_failure(stbi_failure_reason()));
  Image image(width, height);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) image.pixels[i][c] = srgb_to_linear(data[3 * i + c] / 255.0f);
  stbi_image_free(data);
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

Image read_exr(const fs::path& file) {
  try {
    Imf::InputFile in(file.c_str());
    const auto window = in.header().dataWindow();
    const int width = window.max.x - window.min.x + 1, height = window.max.y - window.min.y + 1;
    Image image(width, height);
    Imf::FrameBuffer frame;
    char* origin = reinterpret_cast<char*>(image.pixels.data()) -
                   (static_cast<std::ptrdiff_t>(window.min.y) * width + window.min.x) * sizeof(glm::vec3);
    for (int c = 0; c < 3; ++c)
      frame.insert(exr_channels[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), sizeof(glm::vec3),
                                               sizeof(glm::vec3) * width, 1, 1, 0.0));
    in.setFrameBuffer(frame);
    in.readPixels(window.min.y, window.max.y);
    return image;
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

Image read_image(const fs::path& file) {
  if (!fs::is_regular_file(file)) throw InputError(file.string(), "", "no such file");
  const std::string ext = extension(file);
  if (ext == ".png") return read_png(file);
  if (ext == ".pfm") return read_pfm(file);
  if (ext == ".exr") return read_exr(file);
  throw InputError(file.string(), "", "unknown image format '" + ext + "' (use .png, .pfm or .exr)");
}

}  // namespace airlight
