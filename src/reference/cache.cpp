#include "reference/cache.hpp"

#include "core/atomic_file.hpp"
#include "core/warning.hpp"

#include <airlight/error.hpp>

#include <nlohmann/json.hpp>

#include <charconv>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string_view>

namespace airlight::reference {

namespace fs = std::filesystem;

fs::path default_cache_dir() {
  if (const char* dir = std::getenv("AIRLIGHT_CACHE"); dir && *dir) return dir;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "airlight";
  if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".cache" / "airlight";
  return fs::temp_directory_path() / "airlight-cache";  // no home: still a usable cache for this machine
}

namespace {

// 64-bit FNV-1a over the fields one by one (never whole structs, whose padding
// bytes are indeterminate).
class Hasher {
public:
  void bytes(const void* data, size_t n) {
    for (const auto* p = static_cast<const unsigned char*>(data); n--; ++p) hash_ = (hash_ ^ *p) * 0x100000001b3ull;
  }
  template <typename T>
  void add(const T& value) {
    bytes(&value, sizeof value);
  }
  void add(const glm::vec3& v) { bytes(&v[0], 3 * sizeof(float)); }
  void add(const glm::vec2& v) { bytes(&v[0], 2 * sizeof(float)); }
  void add(std::string_view text) {
    add(text.size());
    bytes(text.data(), text.size());
  }
  template <typename T>
  void add(const std::vector<T>& items) {
    add(items.size());
    for (const auto& item : items) add(item);
  }
  std::uint64_t value() const { return hash_; }

private:
  std::uint64_t hash_ = 0xcbf29ce484222325ull;
};

void add(Hasher& h, const Phase& phase) {
  h.add(phase.lobes.size());
  for (const auto& lobe : phase.lobes) {
    h.add(lobe.type);
    h.add(lobe.g);
    h.add(lobe.weight);
  }
}

void add(Hasher& h, const Image& image) {
  h.add(image.width);
  h.add(image.height);
  h.add(image.pixels);
}

void add(Hasher& h, const Camera& c) {
  for (const auto& v : {c.position, c.look_at, c.up}) h.add(v);
  for (float f : {c.fov_y_deg, c.near, c.far}) h.add(f);
}

void add(Hasher& h, const Light& light) {
  h.add(light.type);
  for (const auto& v : {light.position, light.direction, light.intensity, light.irradiance, light.gobo_up}) h.add(v);
  h.add(light.cone_deg);
  h.add(light.edge_deg);
  h.add(light.gobo != nullptr);
  if (light.gobo) add(h, *light.gobo);
  h.add(light.beam.has_value());
  if (light.beam) {
    h.add(light.beam->origin);
    h.add(light.beam->size);
    h.add(light.beam->length);
  }
}

void add(Hasher& h, const Volume& v) {
  for (const auto& c : {v.min, v.max, v.sigma_s, v.sigma_a}) h.add(c);
  add(h, v.phase);
}

void add(Hasher& h, const Mesh& mesh) {
  h.add(mesh.positions);
  h.add(mesh.normals);
  h.add(mesh.triangles.size());
  for (const auto& t : mesh.triangles) h.bytes(&t[0], 3 * sizeof(unsigned));
  h.add(mesh.albedo);
  h.add(mesh.casts_shadows);
}

template <typename T>
void add_all(Hasher& h, const std::vector<T>& items) {
  h.add(items.size());
  for (const auto& item : items) add(h, item);
}

// One file per entry (README "The reference cache"), renamed into place whole:
//   "airlight-reference-entry/1 fnv1a64=<16 hex> bytes=<N>\n", then N bytes:
//   a JSON line {"width", "height", "seconds"}, then the airlight's and the
//   surface's pixels as float32 RGB, top row first, in the host's byte order.
// The first line's size and checksum cover the rest, so a truncated, grown or
// damaged entry is found before any of it is used.
constexpr std::string_view entry_format = "airlight-reference-entry/1";

fs::path entry_file(const fs::path& dir, const std::string& key) { return dir / (key + ".ref"); }

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

std::string checksum(std::string_view bytes) {
  Hasher h;
  h.bytes(bytes.data(), bytes.size());
  return hex(h.value());
}

std::string_view pixel_bytes(const Image& image) {
  return {reinterpret_cast<const char*>(image.pixels.data()), image.pixels.size() * sizeof(glm::vec3)};
}

void store(const CachedReference& frame, const fs::path& file) {
  const std::string body = nlohmann::json{{"width", frame.airlight.width},
                                          {"height", frame.airlight.height},
                                          {"seconds", frame.seconds}}.dump() +
                           "\n" + std::string(pixel_bytes(frame.airlight)) + std::string(pixel_bytes(frame.surface));
  write_atomically(file, [&](const fs::path& temp) {
    std::ofstream out(temp, std::ios::binary);
    out << entry_format << " fnv1a64=" << checksum(body) << " bytes=" << body.size() << "\n" << body;
    if (!out.flush()) throw Failure("cannot write " + temp.string());
  });
}

// Read at once by its size: through a stringstream, reading an entry took ten
// times as long as checking its checksum (docs/decisions.md "The reference cache").
std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  std::string bytes(in ? static_cast<size_t>(in.tellg()) : 0, '\0');
  in.seekg(0);
  in.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<size_t>(in.gcount()));
  return bytes;
}

// The first line's checksum and byte count, or nothing when it is not one.
std::optional<std::pair<std::string, size_t>> first_line(std::string_view line) {
  std::istringstream words{std::string(line)};
  std::string format, sum, bytes;
  words >> format >> sum >> bytes;
  size_t count = 0;
  const bool parsed = format == entry_format && sum.rfind("fnv1a64=", 0) == 0 && sum.size() == 24 &&
                      bytes.rfind("bytes=", 0) == 0 &&
                      std::from_chars(bytes.data() + 6, bytes.data() + bytes.size(), count).ec == std::errc{};
  if (!parsed) return std::nullopt;
  return std::make_pair(sum.substr(8), count);
}

// What is wrong with an entry's bytes for a frame of width × height, or "" when
// nothing is and `frame` holds it.
std::string entry_fault(std::string_view text, int width, int height, CachedReference* frame) {
  const size_t eol = text.find('\n');
  const auto first = first_line(text.substr(0, eol));
  if (eol == std::string_view::npos || !first) return "not a reference cache entry (its first line is damaged)";
  const auto& [sum, bytes] = *first;
  const std::string_view body = text.substr(eol + 1);
  if (body.size() != bytes)
    return "size check failed: " + std::to_string(body.size()) + " bytes after the first line, which says " +
           std::to_string(bytes);
  if (const std::string actual = checksum(body); actual != sum)
    return "checksum check failed: the content's FNV-1a is " + actual + ", the first line says " + sum;
  const size_t meta_end = body.find('\n');
  const nlohmann::json meta = nlohmann::json::parse(body.substr(0, meta_end), nullptr, false);
  const auto number = [&](const char* key) {
    const auto it = meta.is_object() ? meta.find(key) : meta.end();
    return it != meta.end() && it->is_number() ? it->get<double>() : -1.0;
  };
  const size_t image_bytes = static_cast<size_t>(width) * height * sizeof(glm::vec3);
  if (meta_end == std::string_view::npos || number("width") != width || number("height") != height ||
      body.size() - meta_end - 1 != 2 * image_bytes)
    return "its metadata is not that of a " + std::to_string(width) + "x" + std::to_string(height) + " frame";
  frame->airlight = frame->surface = Image(width, height);
  std::memcpy(frame->airlight.pixels.data(), body.data() + meta_end + 1, image_bytes);
  std::memcpy(frame->surface.pixels.data(), body.data() + meta_end + 1 + image_bytes, image_bytes);
  frame->seconds = number("seconds");
  frame->cached = true;
  return "";
}

// The cached frame, or none when absent; a damaged entry is reported and
// rendered again (and overwritten).
std::optional<CachedReference> load(const fs::path& file, int width, int height) {
  std::error_code ec;
  if (!fs::exists(file, ec)) return std::nullopt;
  CachedReference frame;
  const std::string fault = entry_fault(file_bytes(file), width, height, &frame);
  if (fault.empty()) return frame;
  warn(file.string(), fault + "; rendering the reference again");
  return std::nullopt;
}

CachedReference render_reference(const Scene& scene, int width, int height, const Settings& settings) {
  const auto start = std::chrono::steady_clock::now();
  Images frame = render(scene, width, height, settings);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return {std::move(frame.airlight), std::move(frame.surface), seconds, false};
}

}  // namespace

std::string reference_key(const Scene& scene, int width, int height, const Settings& settings) {
  Hasher h;
  h.add(std::string_view("airlight-reference/5"));  // bump when the reference's output or the key changes
  add(h, scene.camera);
  for (const auto& c : {scene.medium.sigma_s, scene.medium.sigma_a}) h.add(c);
  add(h, scene.medium.phase);
  h.add(scene.light_model.type);
  h.add(scene.light_model.a0);
  h.add(scene.light_model.a1);
  add_all(h, scene.volumes);
  add_all(h, scene.lights);
  add_all(h, scene.meshes);
  h.add(scene.ambient);
  h.add(width);
  h.add(height);
  h.add(settings.rel_tol);
  h.add(settings.min_segments);
  h.add(settings.subpixel.x);
  h.add(settings.subpixel.y);
  for (const bool rendered : settings.pixels) h.add(rendered ? 1 : 0);  // none when all are
  if (!settings.airlight) h.add(0);                                      // nothing by default
  return hex(h.value());
}

CachedReference cached_reference(const Scene& scene, int width, int height, const fs::path& cache_dir,
                                 const Settings& settings) {
  const fs::path file = entry_file(cache_dir, reference_key(scene, width, height, settings));
  if (auto frame = load(file, width, height)) return *frame;
  std::error_code ec;
  fs::create_directories(cache_dir, ec);
  if (ec) throw Failure("cannot create the reference cache " + cache_dir.string() + ": " + ec.message());
  CachedReference frame = render_reference(scene, width, height, settings);
  store(frame, file);
  return frame;
}

}  // namespace airlight::reference
