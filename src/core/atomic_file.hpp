#pragma once
// Output files appear whole or not at all: each is written under a unique name
// beside its target and renamed over it once complete, so a failure or a
// concurrent reader never sees half a file.
#include <filesystem>
#include <functional>
#include <string>

namespace airlight {

// Calls write(temp) with a fresh name in the target's directory that keeps the
// target's extension (writers pick the format by it), then renames temp over
// `target`. Removes temp when write throws. Throws Failure when the rename fails.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& temp)>& write);

// `text` into `file`, atomically; Failure when it cannot be written.
void write_text_file(const std::filesystem::path& file, const std::string& text);

}  // namespace airlight
