#include "app/output_check.hpp"

#include "core/listed.hpp"
#include "core/number_text.hpp"
#include "gpu/gl.hpp"

#include <airlight/error.hpp>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <tuple>

namespace airlight::app {

namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// The directory a relative name lives in is the working directory.
fs::path directory_of(const fs::path& file) { return file.has_parent_path() ? file.parent_path() : fs::path("."); }

void check_writable_directory(const std::string& option, const fs::path& named, const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw InputError(option, named.string(), "no such directory: " + dir.string());
  if (!fs::is_directory(dir, ec)) throw InputError(option, named.string(), "not a directory: " + dir.string());
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw InputError(option, named.string(), "cannot write in " + dir.string() + " (permission denied)");
}

std::string memory_text(double bytes) {
  const double mib = bytes / (1024.0 * 1024.0);
  char text[32];
  if (mib < 1024.0)
    std::snprintf(text, sizeof text, "%.0f MiB", mib);
  else
    std::snprintf(text, sizeof text, "%.1f GiB", mib / 1024.0);
  return text;
}

// MemAvailable in /proc/meminfo, in kB; sysconf's physical memory where there is none.
std::uint64_t machine_memory() {
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;) {
    std::uint64_t kb = 0;
    if (key == "MemAvailable:" && meminfo >> kb) return kb * 1024;
    meminfo.ignore(256, '\n');
  }
  return static_cast<std::uint64_t>(::sysconf(_SC_PHYS_PAGES)) * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

}  // namespace

void check_output_file(const std::string& option, const fs::path& file, const std::vector<std::string>& extensions) {
  const std::string ext = lower_extension(file);
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end())
    throw InputError(option, file.string(),
                     (ext.empty() ? std::string("no extension") : "unknown extension '" + ext + "'") + " (use " +
                         listed(extensions, "or") + ")");
  check_writable_directory(option, file, directory_of(file));
  std::error_code ec;
  if (fs::is_directory(file, ec)) throw InputError(option, file.string(), "is a directory");
  if (fs::exists(file, ec) && ::access(file.c_str(), W_OK) != 0)
    throw InputError(option, file.string(), "cannot replace it (permission denied)");
}

void check_output_dir(const std::string& option, const fs::path& dir) {
  std::error_code ec;
  fs::path existing = dir;
  while (!existing.empty() && !fs::exists(existing, ec)) existing = existing.parent_path();
  check_writable_directory(option, dir, existing.empty() ? fs::path(".") : existing);
}

std::uint64_t memory_available() {
  if (const char* text = std::getenv("AIRLIGHT_MEMORY_MIB"); text && *text) {
    std::uint64_t mib = 0;
    const char* end = text + std::char_traits<char>::length(text);
    const auto [stop, ec] = std::from_chars(text, end, mib);
    if (ec != std::errc() || stop != end || mib == 0)
      throw InputError("AIRLIGHT_MEMORY_MIB", text, "must be a whole number of MiB, at least 1");
    return mib * 1024 * 1024;
  }
  return machine_memory();
}

namespace {

std::string setting_text(const Settings& settings, const std::string& name) {
  const nlohmann::json value = settings.to_json().at(name);
  return name + "=" + (value.is_string()         ? value.get<std::string>()
                       : value.is_number_float() ? number_text(value.get<double>())
                                                 : value.dump());
}

// A run's frame: its per-pixel part and its buffers, the largest first.
struct FramePlan {
  double per_pixel = 0.0, total = 0.0;
  std::vector<MemoryNeed> needs;
};

FramePlan frame_plan(const Scene& scene, Size size, const MethodRun& run, int kept_images) {
  FramePlan plan;
  plan.per_pixel = double(size.width) * size.height * (run.info->bytes_per_pixel + 12.0 * kept_images);
  if (run.info->memory && run.settings) plan.needs = run.info->memory(scene, *run.settings, size.width, size.height);
  std::sort(plan.needs.begin(), plan.needs.end(), [](const auto& a, const auto& b) { return a.bytes > b.bytes; });
  plan.total = plan.per_pixel;
  for (const MemoryNeed& need : plan.needs) plan.total += need.bytes;
  return plan;
}

// The option and value a refusal names for `need`: the setting, or the scene.
InputError blame(const Scene& scene, const MethodRun& run, const MemoryNeed& need, bool qualified, const std::string& why) {
  if (!need.setting.empty())
    return InputError("--set", (qualified ? run.info->name + "." : std::string()) + setting_text(*run.settings, need.setting),
                      why);
  if (scene.source.empty()) return InputError("--builtin", scene.name, why);
  return InputError(scene.source.string(), "", why);
}

// A frame's RGBA float targets, and each need's largest buffer and texture,
// within what one OpenGL object holds (gpu/gl.hpp).
void check_objects(const Scene& scene, const std::string& size_option, Size size, const MethodRun& run,
                   const FramePlan& plan, bool qualified) {
  const double target = 16.0 * size.width * size.height;
  if (target >= gpu::max_texture_bytes)
    throw InputError(size_option, std::to_string(size.width) + "x" + std::to_string(size.height),
                     "one RGBA float target of this size is " + memory_text(target) + ", more than the " +
                         memory_text(gpu::max_texture_bytes) + " one OpenGL texture holds on Mesa");
  for (const MemoryNeed& need : plan.needs)
    for (const auto& [bytes, limit, object] : {std::tuple{need.largest_buffer, gpu::max_buffer_bytes + 1.0, "buffer"},
                                               std::tuple{need.largest_texture, gpu::max_texture_bytes, "texture"}})
      if (bytes >= limit)
        throw blame(scene, run, need, qualified,
                    run.info->name + " needs " + memory_text(bytes) + " in one OpenGL " + object + " for " + need.what +
                        ", more than the " + memory_text(limit) + " one " + object + " holds on Mesa");
}

[[noreturn]] void refuse(const Scene& scene, const std::string& size_option, Size size, const MethodRun& run,
                         int kept_images, const FramePlan& plan, bool qualified) {
  const std::string available = memory_text(double(memory_available()));
  const std::string& method = run.info->name;
  if (plan.needs.empty() || plan.per_pixel >= plan.needs.front().bytes) {
    std::string why = "needs about " + memory_text(plan.total) + " of memory (" + method + ": " +
                      std::to_string(run.info->bytes_per_pixel) + " bytes per pixel";
    if (kept_images > 0) why += ", and 12 for each of " + std::to_string(kept_images) + " images kept";
    if (plan.total > plan.per_pixel) why += ", and " + memory_text(plan.total - plan.per_pixel) + " for its buffers";
    throw InputError(size_option, std::to_string(size.width) + "x" + std::to_string(size.height),
                     why + "), more than the " + available + " available");
  }
  const MemoryNeed& largest = plan.needs.front();
  const std::string why = method + " needs about " + memory_text(plan.total) + " of memory, " +
                          memory_text(largest.bytes) + " of it for " + largest.what + ", more than the " + available +
                          " available";
  throw blame(scene, run, largest, qualified, why);
}

}  // namespace

void check_memory(const std::string& option, Size size, const std::vector<const MethodInfo*>& methods,
                  int kept_images) {
  const MethodInfo* largest = *std::max_element(
      methods.begin(), methods.end(), [](const auto* a, const auto* b) { return a->bytes_per_pixel < b->bytes_per_pixel; });
  const MethodRun run{largest, nullptr};
  const FramePlan plan = frame_plan(Scene{}, size, run, kept_images);
  if (plan.total > double(memory_available())) refuse(Scene{}, option, size, run, kept_images, plan, false);
  check_objects(Scene{}, option, size, run, plan, false);
}

void check_limits(const Scene& scene, const MethodRun& run, bool qualified) {
  for (const SceneLimit& limit : run.info->limits) {
    const double count = limit.count(scene), bound = run.settings->integer(limit.setting);
    if (count <= bound) continue;
    const std::string name = scene.source.empty() ? scene.name : scene.source.string();
    const std::string key = (qualified ? run.info->name + "." : std::string()) + setting_text(*run.settings, limit.setting);
    throw InputError("--set", key,
                     "the scene " + name + " has " + std::to_string(static_cast<long long>(count)) + " " +
                         limit.counted + ", more than " + run.info->name + " takes at this setting (" + limit.why +
                         "); a larger " + limit.setting + " renders it anyway");
  }
}

void check_frame_memory(const Scene& scene, const std::string& size_option, Size size, const std::vector<MethodRun>& runs,
                        int kept_images, bool qualified) {
  const double available = double(memory_available());
  for (const MethodRun& run : runs) {
    check_limits(scene, run, qualified);
    const FramePlan plan = frame_plan(scene, size, run, kept_images);
    if (plan.total > available) refuse(scene, size_option, size, run, kept_images, plan, qualified);
    check_objects(scene, size_option, size, run, plan, qualified);
  }
}

std::string memory_hint(const Scene& scene, Size size, const MethodRun& run) {
  const FramePlan plan = frame_plan(scene, size, run, 0);
  std::string hint = run.info->name + " plans on about " + memory_text(plan.total) + " for this frame";
  if (plan.needs.empty() || plan.per_pixel >= plan.needs.front().bytes)
    return hint + ", most of it per pixel: a smaller --size is the likely fix";
  const MemoryNeed& largest = plan.needs.front();
  hint += ", " + memory_text(largest.bytes) + " of it for " + largest.what;
  if (largest.setting.empty()) return hint + ": the scene's lights and casters";
  return hint + ": the setting most likely responsible is " + setting_text(*run.settings, largest.setting);
}

void with_memory_hint(const Scene& scene, Size size, const MethodRun& run, const std::function<void()>& render) {
  try {
    render();
  } catch (const OutOfMemory& e) {
    throw OutOfMemory(std::string(e.what()) + "\n" + memory_hint(scene, size, run));
  }
}

}  // namespace airlight::app
