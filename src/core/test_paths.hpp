#pragma once
// Where a test finds the project's files and the `airlight` command. The build gives
// each test these places relative to the test's own executable (airlight_test in the
// top CMakeLists.txt), not as absolute paths, so a test's object is the same in every
// preset and every checkout and ccache reuses it (docs/decisions.md "Build").
#include <filesystem>

namespace airlight::test {

// The folder of the running test executable.
inline std::filesystem::path executable_dir() {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path();
}

inline std::filesystem::path source_dir() {
  return (executable_dir() / AIRLIGHT_SOURCE_FROM_TEST).lexically_normal();
}
inline std::filesystem::path test_data() { return source_dir() / "tests" / "data"; }
inline std::filesystem::path bench_scenes() { return source_dir() / "bench" / "scenes"; }
// The `airlight` command of the same build.
inline std::filesystem::path airlight_exe() {
  return (executable_dir() / AIRLIGHT_EXE_FROM_TEST).lexically_normal();
}

}  // namespace airlight::test
