#include "app/output_check.hpp"

#include <airlight/error.hpp>

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace airlight::app {

namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string listed(const std::vector<std::string>& items) {
  std::string text;
  for (size_t i = 0; i < items.size(); ++i) text += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
  return text;
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
                         listed(extensions) + ")");
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

void check_memory(const std::string& option, Size size, const std::vector<const MethodInfo*>& methods,
                  int kept_images) {
  const MethodInfo* largest = *std::max_element(
      methods.begin(), methods.end(), [](const auto* a, const auto* b) { return a->bytes_per_pixel < b->bytes_per_pixel; });
  const double pixels = double(size.width) * size.height;
  const double rgb_float = 12.0;  // an Image's pixel
  const double needed = pixels * (largest->bytes_per_pixel + rgb_float * kept_images);
  const std::uint64_t available = memory_available();
  if (needed <= double(available)) return;
  std::string why = "needs about " + memory_text(needed) + " of memory (" + largest->name + ": " +
                    std::to_string(largest->bytes_per_pixel) + " bytes per pixel";
  if (kept_images > 0) why += ", and 12 for each of " + std::to_string(kept_images) + " images kept";
  throw InputError(option, std::to_string(size.width) + "x" + std::to_string(size.height),
                   why + "), more than the " + memory_text(double(available)) + " available");
}

}  // namespace airlight::app
