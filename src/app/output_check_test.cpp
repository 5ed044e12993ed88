// Outputs and sizes are checked before any work (docs/design.md §5): with EGL
// pointed at an empty vendor directory no OpenGL context can exist, so a GPU
// method that got as far as its context would exit 1; these exit 2 with the
// reason, which proves the checks ran first. Nothing is left on disk.
#include "app/command_test_support.hpp"

#include <fstream>

namespace airlight {
namespace {

using namespace test;

// No EGL vendor at all: libglvnd finds no driver to load.
std::string no_gl() {
  const fs::path empty = work_dir() / "empty_egl_vendors";
  fs::create_directories(empty);
  return "__EGL_VENDOR_LIBRARY_DIRS=" + empty.string() + " __EGL_VENDOR_LIBRARY_FILENAMES=";
}

const std::string render_gpu = "render --builtin teapot_spot --method raymarch --size 16x12";

void expect_refused(const std::string& args, const std::string& message, const std::string& env = no_gl()) {
  const Outcome o = run_airlight(args, env);
  EXPECT_EQ(o.status, 2) << args << "\n" << o.err;
  EXPECT_EQ(o.err, "airlight: error: " + message + "\n") << args;
}

TEST(OutputCheck, WithoutOpenGlAGpuRenderExitsOne) {
  // The control: the same environment does stop a render that passes the checks.
  const Outcome o = run_airlight(render_gpu + " --out " + (work_dir() / "ok.pfm").string(), no_gl());
  EXPECT_EQ(o.status, 1) << o.err;
  EXPECT_FALSE(fs::exists(work_dir() / "ok.pfm"));
}

TEST(OutputCheck, BadOutputPathsExitTwoBeforeAnyOpenGl) {
  const fs::path dir = work_dir(), missing = dir / "no_such_dir";
  const fs::path file = write_file("plain.txt", "not a directory");
  fs::create_directories(dir / "folder.png");
  expect_refused(render_gpu + " --out " + (missing / "a.png").string(),
                 "--out: " + (missing / "a.png").string() + ": no such directory: " + missing.string());
  expect_refused(render_gpu + " --out " + (file / "a.png").string(),
                 "--out: " + (file / "a.png").string() + ": not a directory: " + file.string());
  expect_refused(render_gpu + " --out " + (dir / "a.jpg").string(),
                 "--out: " + (dir / "a.jpg").string() + ": unknown extension '.jpg' (use .png, .pfm or .exr)");
  expect_refused(render_gpu + " --out " + (dir / "a").string(),
                 "--out: " + (dir / "a").string() + ": no extension (use .png, .pfm or .exr)");
  expect_refused(render_gpu + " --out " + (dir / "folder.png").string(),
                 "--out: " + (dir / "folder.png").string() + ": is a directory");
  expect_refused(render_gpu + " --out " + (dir / "a.png").string() + " --report " + (missing / "r.json").string(),
                 "--report: " + (missing / "r.json").string() + ": no such directory: " + missing.string());
  expect_refused(render_gpu + " --out " + (dir / "a.png").string() + " --report " + (dir / "r.txt").string(),
                 "--report: " + (dir / "r.txt").string() + ": unknown extension '.txt' (use .json)");
  expect_refused("compare --builtin teapot_spot --methods raymarch --size 16x12 --out " + (dir / "s.png").string() +
                     " --images " + (file / "images").string(),
                 "--images: " + (file / "images").string() + ": not a directory: " + file.string());
  expect_refused("compare --builtin teapot_spot --methods raymarch --size 16x12 --out " + (dir / "s.png").string() +
                     " --csv " + (missing / "c.csv").string(),
                 "--csv: " + (missing / "c.csv").string() + ": no such directory: " + missing.string());
  expect_refused("bench --builtin teapot_spot --methods raymarch --csv " + (dir / "b.csv").string() + " --plot " +
                     (dir / "b.svg").string(),
                 "--plot: " + (dir / "b.svg").string() + ": unknown extension '.svg' (use .png)");
  for (const char* name : {"a.png", "r.json", "s.png", "c.csv", "b.csv"}) EXPECT_FALSE(fs::exists(dir / name)) << name;
}

// 1024² by raymarch at 160 bytes per pixel is 160 MiB: refused with 64 MiB to plan on.
TEST(OutputCheck, SizeBeyondTheMemoryExitsTwoBeforeAnyOpenGl) {
  const std::string out = " --out " + (work_dir() / "big.png").string();
  expect_refused("render --builtin teapot_spot --method raymarch --size 1024x1024" + out,
                 "--size: 1024x1024: needs about 160 MiB of memory (raymarch: 160 bytes per pixel), more than the "
                 "64 MiB available",
                 no_gl() + " AIRLIGHT_MEMORY_MIB=64");
  // compare keeps the reference's two images and one per method besides the largest frame: 224 + 4·12 bytes.
  expect_refused("compare --builtin teapot_spot --methods raymarch,shadow_planes --size 1024x1024" + out,
                 "--size: 1024x1024: needs about 272 MiB of memory (shadow_planes: 224 bytes per pixel, and 12 for each "
                 "of 4 images kept), more than the 256 MiB available",
                 no_gl() + " AIRLIGHT_MEMORY_MIB=256");
  expect_refused("render --builtin teapot_spot --size 8x8" + out,
                 "AIRLIGHT_MEMORY_MIB: lots: must be a whole number of MiB, at least 1", "AIRLIGHT_MEMORY_MIB=lots");
  EXPECT_FALSE(fs::exists(work_dir() / "big.png"));
}

// 16384² is the largest size the command parses: 40 GiB by raymarch, more than
// these machines have, refused on the machine's own available memory.
TEST(OutputCheck, TheLargestSizeIsRefusedUpFrontOnThisMachine) {
  std::ifstream meminfo("/proc/meminfo");
  std::uint64_t available_kb = 0;
  for (std::string key; meminfo >> key;)
    if (key == "MemAvailable:") meminfo >> available_kb;
  if (available_kb * 1024.0 > 16384.0 * 16384.0 * 160.0) GTEST_SKIP() << "this machine has 40 GiB available";
  const Outcome o = run_airlight("render --builtin teapot_spot --method raymarch --size 16384x16384 --out " +
                                     (work_dir() / "huge.png").string(),
                                 no_gl());
  EXPECT_EQ(o.status, 2) << o.err;
  const std::string start = "airlight: error: --size: 16384x16384: needs about 40.0 GiB of memory (raymarch: 160 "
                            "bytes per pixel), more than the ";
  EXPECT_EQ(o.err.rfind(start, 0), 0u) << o.err;
}

}  // namespace
}  // namespace airlight
