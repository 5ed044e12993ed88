#pragma once
// What a command will write and how big it renders, checked before any scene is
// loaded or OpenGL touched (docs/design.md §5): a bad path or an impossible size
// exits 2 at once, never after minutes of rendering. Each refusal is an
// InputError naming the option.
#include "app/scene_source.hpp"

#include <airlight/method.hpp>

#include <cstdint>
#include <filesystem>
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

}  // namespace airlight::app
