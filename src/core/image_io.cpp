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
  // Each side first: an EXR's sides reach 2^32, whose product overflows.
  if (width > max_decoded_pixels || height > max_decoded_pixels || width * height > max_decoded_pixels)
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

std::uint32_t big_endian_u32(const std::string& bytes, size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return __builtin_bswap32(v);
}

std::uint32_t little_endian_u32(const std::string& bytes, size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;
}

// stb_image grows its buffer to a chunk's stated length before reading the chunk:
// every chunk up to IEND must lie inside the file first.
bool png_chunks_inside(const std::string& bytes) {
  for (size_t at = 8; at + 8 <= bytes.size();) {
    const std::uint64_t length = big_endian_u32(bytes, at);
    if (length + 12 > bytes.size() - at) return false;
    if (bytes.compare(at + 4, 4, "IEND") == 0) return true;
    at += length + 12;
  }
  return false;
}

// PNG only: stb_image would decode a dozen other formats behind a .png name.
Image read_png(const std::string& bytes, const fs::path& file) {
  static constexpr std::string_view signature = "\x89PNG\r\n\x1a\n";
  if (!bytes.starts_with(signature)) unreadable(file, png_failure("unknown image type"));
  if (!png_chunks_inside(bytes)) unreadable(file, png_failure("outofdata"));
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

// Whether an attribute's value of `size` bytes at `at` is what OpenEXR's reader of its
// type reads: those read their own layout, whatever the stated size, and some
// allocate a count the value gives before reading it.
bool exr_value_fits(const std::string& bytes, const std::string& type, size_t at, std::uint32_t size) {
  static const std::map<std::string, std::uint32_t> fixed = {
      {"box2i", 16},    {"box2f", 16}, {"chromaticities", 32}, {"compression", 1}, {"double", 8},
      {"envmap", 1},    {"float", 4},  {"int", 4},             {"keycode", 28},    {"lineOrder", 1},
      {"m33f", 36},     {"m33d", 72},  {"m44f", 64},           {"m44d", 128},      {"rational", 8},
      {"tiledesc", 9},  {"timecode", 8}, {"v2i", 8},           {"v2f", 8},         {"v2d", 16},
      {"v3i", 12},      {"v3f", 12},   {"v3d", 24},            {"deepImageState", 1}};
  if (const auto it = fixed.find(type); it != fixed.end()) return size == it->second;
  const size_t end = at + size;
  if (type == "chlist") {  // entries of a name and 16 bytes, then an empty name
    while (at < end && bytes[at] != '\0') {
      const size_t name_end = bytes.find('\0', at);
      if (name_end >= end || end - name_end - 1 < 16) return false;
      at = name_end + 17;
    }
    return at + 1 == end;
  }
  if (type == "stringvector") {  // strings, each after its length
    while (at < end) {
      if (end - at < 4 || little_endian_u32(bytes, at) > end - at - 4) return false;
      at += 4 + little_endian_u32(bytes, at);
    }
    return true;
  }
  if (type == "preview")  // width, height, then 4 bytes a pixel
    return size >= 8 && std::uint64_t(little_endian_u32(bytes, at)) * little_endian_u32(bytes, at + 4) * 4 == size - 8;
  if (type == "floatvector") return size % 4 == 0;
  return type != "idmanifest";  // compressed, it states its own size; any other type is read as `size` bytes
}

// OpenEXR allocates what a header states before it reads it: the header is walked here
// first, every attribute inside the file and of the size its type reads, a single-part
// scanline image whose data window has at most max_decoded_pixels (OpenEXR's file
// layout, "The Header").
void check_exr_header(const std::string& bytes, const fs::path& file) {
  const auto fail = [&](const std::string& why) { unreadable(file, "cannot read EXR: " + why); };
  if (bytes.size() < 8 || little_endian_u32(bytes, 0) != 20000630) fail("not an OpenEXR file");
  constexpr std::uint32_t tiled = 0x200, long_names = 0x400, deep = 0x800, multipart = 0x1000;
  const std::uint32_t flags = little_endian_u32(bytes, 4);
  if (flags & (tiled | deep | multipart)) fail("a tiled, deep or multi-part file: airlight reads single-part scanline images");
  const size_t longest_name = flags & long_names ? 255 : 31;
  // A name or type name, null-terminated, no longer than OpenEXR reads; returns its end.
  const auto name_end = [&](size_t at) {
    const size_t end = bytes.find('\0', at);
    if (end == std::string::npos) fail("the header is cut short");
    if (end - at > longest_name) fail("the header has a name longer than " + std::to_string(longest_name) + " characters");
    return end;
  };
  bool window = false;
  for (size_t at = 8;;) {
    const size_t end = name_end(at);
    if (end == at) break;  // an empty name ends the header
    const std::string name = bytes.substr(at, end - at);
    const size_t type_end = name_end(end + 1);
    const std::string type = bytes.substr(end + 1, type_end - end - 1);
    if (bytes.size() - type_end < 5) fail("the header is cut short");
    const std::uint32_t size = little_endian_u32(bytes, type_end + 1);
    at = type_end + 5;
    if (size > bytes.size() - at) fail("the header's attribute \"" + name + "\" runs past the end of the file");
    if (!exr_value_fits(bytes, type, at, size))
      fail("the header's attribute \"" + name + "\" is not a well-formed " + type);
    if (name == "dataWindow" && type == "box2i") {
      const auto coordinate = [&](int i) {
        return static_cast<long long>(static_cast<std::int32_t>(little_endian_u32(bytes, at + 4 * i)));
      };
      check_pixels(std::max(0LL, 1 + coordinate(2) - coordinate(0)), std::max(0LL, 1 + coordinate(3) - coordinate(1)),
                   file);
      window = true;
    }
    at += size;
  }
  if (!window) fail("the header has no dataWindow");
}

Image read_exr(const std::string& bytes, const fs::path& file) {
  check_exr_header(bytes, file);
  // Besides the header's walk, OpenEXR's own check of a side against a render's largest.
  static const bool bounded = [] {
    Imf::Header::setMaxImageSize(16384, 16384);
    return true;
  }();
  (void)bounded;
  try {
    MemoryStream stream(bytes, file);
    Imf::InputFile in(stream);
    const auto window = in.header().dataWindow();
    const long long width = 1LL + window.max.x - window.min.x, height = 1LL + window.max.y - window.min.y;
    Image image(static_cast<int>(width), static_cast<int>(height));
    Imf::FrameBuffer frame;
    // Slice::Make places the window's corner, whatever its coordinates, at the first pixel.
    for (int c = 0; c < 3; ++c)
      frame.insert(exr_channels[c], Imf::Slice::Make(Imf::FLOAT, &image.pixels[0][c], window, sizeof(glm::vec3),
                                                     sizeof(glm::vec3) * width));
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
