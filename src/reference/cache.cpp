#include "reference/cache.hpp"

#include "core/atomic_file.hpp"
#include "core/image_io.hpp"

#include <airlight/error.hpp>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
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

struct Entry {
  fs::path airlight, surface, info;
};

Entry entry(const fs::path& dir, const std::string& key) {
  return {dir / (key + ".airlight.pfm"), dir / (key + ".surface.pfm"), dir / (key + ".json")};
}

// The JSON is written last, so its presence means both images are complete.
void store(const CachedReference& frame, const Entry& e) {
  write_image(frame.airlight, e.airlight);
  write_image(frame.surface, e.surface);
  write_text_file(e.info, nlohmann::json{{"seconds", frame.seconds}}.dump() + "\n");
}

// The cached frame, or none when absent, unreadable or of another size.
std::optional<CachedReference> load(const Entry& e, int width, int height) {
  std::ifstream info(e.info);
  if (!info) return std::nullopt;
  try {
    CachedReference frame{read_image(e.airlight), read_image(e.surface),
                         nlohmann::json::parse(info).at("seconds").get<double>(), true};
    const bool sized = frame.airlight.width == width && frame.airlight.height == height &&
                       frame.surface.width == width && frame.surface.height == height;
    if (sized) return frame;
  } catch (const std::exception&) {
    // A damaged entry is rendered again and overwritten.
  }
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
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h.value()));
  return hex;
}

CachedReference cached_reference(const Scene& scene, int width, int height, const fs::path& cache_dir,
                                 const Settings& settings) {
  const Entry e = entry(cache_dir, reference_key(scene, width, height, settings));
  if (auto frame = load(e, width, height)) return *frame;
  std::error_code ec;
  fs::create_directories(cache_dir, ec);
  if (ec) throw Failure("cannot create the reference cache " + cache_dir.string() + ": " + ec.message());
  CachedReference frame = render_reference(scene, width, height, settings);
  store(frame, e);
  return frame;
}

}  // namespace airlight::reference
