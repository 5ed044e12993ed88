#pragma once
// What a command will write and how big it renders, checked before any scene is
// loaded or OpenGL touched (docs/design.md §5): a bad path or an impossible size
// exits 2 at once, never after minutes of rendering. Each refusal is an
// InputError naming the option.
#include "app/scene_source.hpp"

#include <airlight/method.hpp>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace airlight::app {

// `file` can be created or replaced: its directory exists and is writable, it is
// not itself a directory, and its extension is one of `extensions` (".png", ...).
void check_output_file(const std::string& option, const std::filesystem::path& file,
                       const std::vector<std::string>& extensions);

// `dir` exists as a writable directory, or can be created: its nearest existing
// ancestor is a writable directory.
void check_output_dir(const std::string& option, const std::filesystem::path& dir);

// The memory a run may plan on: $AIRLIGHT_MEMORY_MIB when set, else the
// machine's available memory (/proc/meminfo's MemAvailable).
std::uint64_t memory_available();

// A frame of `size` by each of `methods` (run one after another), plus
// `kept_images` RGB float images held across them, fits in memory_available().
void check_memory(const std::string& option, Size size, const std::vector<const MethodInfo*>& methods,
                  int kept_images = 0);

// One method with its settings, as a command runs it.
struct MethodRun {
  const MethodInfo* info = nullptr;
  const Settings* settings = nullptr;
};

// The scene is within the run's MethodInfo::limits, else refused naming the
// limit's setting, "--set: key=value", or "method.key=value" when `qualified`
// (docs/decisions.md "A million triangles"). The viewer checks it at each
// change of method or setting.
void check_limits(const Scene& scene, const MethodRun& run, bool qualified = false);

// After the scene is loaded and before any GL allocation: the scene is within
// each run's MethodInfo::limits (else refused naming the limit's setting,
// "--set: key=value", or "method.key=value" when `qualified`), and each run's
// frame of `size` (its bytes per pixel and its MethodInfo::memory), plus
// `kept_images`, fits in memory_available(). Refuses with what takes the most:
// the size, the setting that sizes the largest buffer, or the scene when its
// lights or casters alone do.
void check_frame_memory(const Scene& scene, const std::string& size_option, Size size, const std::vector<MethodRun>& runs,
                        int kept_images = 0, bool qualified = false);

// For a GL_OUT_OF_MEMORY that happened anyway: the run's largest buffer and
// the setting that sizes it, e.g. "the largest buffer: ... (volume_resolution=2048)".
std::string memory_hint(const Scene& scene, Size size, const MethodRun& run);

// Runs `render`, adding memory_hint to an OutOfMemory it throws.
void with_memory_hint(const Scene& scene, Size size, const MethodRun& run, const std::function<void()>& render);

}  // namespace airlight::app
