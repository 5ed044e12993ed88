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

// Settings that size large buffers, refused after the scene is read and before
// any OpenGL (the no-GL environment would exit 1), naming the setting and what
// it sizes (MethodInfo::memory): one case per kind of buffer a method declares.
TEST(OutputCheck, SettingsBeyondTheMemoryExitTwoBeforeAnyOpenGl) {
  const std::string out = " --size 64x48 --out " + (work_dir() / "big.png").string();
  const auto memory = [](int mib) { return no_gl() + " AIRLIGHT_MEMORY_MIB=" + std::to_string(mib); };
  const std::string meshes =
      "the light volume meshes of 1 cube map (6 faces × 6·1024² triangles), 1 spot map (6·1024² triangles and the "
      "sides) and 1 directional map (6·1024² triangles and the sides), 80 bytes a triangle";
  expect_refused("render --builtin three_lights --method light_volume --set volume_resolution=1024" + out,
                 "--set: volume_resolution=1024: light_volume needs about 4.2 GiB of memory, 4.1 GiB of it for " +
                     meshes + ", more than the 1.0 GiB available",
                 memory(1024));
  expect_refused("render --builtin three_lights --method sv_march --set volume_resolution=512" + out,
                 "--set: volume_resolution=512: sv_march needs about 781 MiB of memory, 745 MiB of it for the shells "
                 "of 1 cube map (6 faces × 4·512² triangles), 1 spot map (4·512² triangles and the sides) and 1 "
                 "directional map (4·512² triangles and the sides), 80 bytes a triangle, more than the 512 MiB "
                 "available",
                 memory(512));
  expect_refused("render --builtin teapot_spot --method raymarch --set shadow_resolution=8192" + out,
                 "--set: shadow_resolution=8192: raymarch needs about 513 MiB of memory, 512 MiB of it for the shadow "
                 "maps of 1 light (1 map, 8192² texels of 4 bytes each), more than the 256 MiB available",
                 memory(256));
  expect_refused("render --builtin teapot_spot --method shadow_planes --set capacity=256 --size 256x192 --out " +
                     (work_dir() / "big.png").string(),
                 "--set: capacity=256: shadow_planes needs about 164 MiB of memory, 142 MiB of it for its crossing pool "
                 "(256 crossings of 12 bytes per pixel at 256x192), more than the 128 MiB available",
                 memory(128));
  expect_refused("render --builtin nilsson_multiple --method hybrid --set planes=8192" + out,
                 "--set: planes=8192: hybrid needs about 618 MiB of memory, 609 MiB of it for the slab regions of "
                 "8192 planes across the bounding volumes of 26 casters (about 3 KB per plane and caster), more than "
                 "the 256 MiB available",
                 memory(256));
  // The scene alone: beam_volumes' trees grow with the casters' triangles and the lights.
  expect_refused("render --builtin toth_hall --method beam_volumes" + out,
                 "--builtin: toth_hall: beam_volumes needs about 190 MiB of memory, 158 MiB of it for the beam trees "
                 "and pyramids of 66308 caster triangles and 1 light (about 2.5 KB per triangle and light), more than "
                 "the 64 MiB available",
                 memory(64));
  // compare, bench and view check the same, compare and bench with the method's name in front.
  const std::string qualified = "--set: light_volume.volume_resolution=1024: light_volume needs about 4.2 GiB of "
                                "memory, 4.1 GiB of it for " + meshes + ", more than the 1.0 GiB available";
  expect_refused("compare --builtin three_lights --methods raymarch,light_volume:volume_resolution=1024" + out,
                 qualified, memory(1024));
  expect_refused("bench --builtin three_lights --methods light_volume --sweep light_volume.volume_resolution=64,1024 "
                 "--sizes 64x48 --csv " + (work_dir() / "big.csv").string(),
                 qualified, memory(1024));
  expect_refused("view --builtin three_lights --method light_volume --set volume_resolution=1024 --size 64x48",
                 "--set: volume_resolution=1024: light_volume needs about 4.2 GiB of memory, 4.1 GiB of it for " +
                     meshes + ", more than the 1.0 GiB available",
                 memory(1024));
  EXPECT_FALSE(fs::exists(work_dir() / "big.png"));
  EXPECT_FALSE(fs::exists(work_dir() / "big.csv"));
}

// A scene beyond a method's limit (MethodInfo::limits), refused after it is
// read and before any OpenGL, naming the setting; at the limit it passes the
// check (and the no-GL environment stops it, exit 1). Two lights over a box:
// 24 caster triangles and 72 edges summed over the lights.
TEST(OutputCheck, ScenesBeyondAMethodsLimitExitTwoBeforeAnyOpenGl) {
  const fs::path scene = write_file("limits.json", R"({"format": "airlight-scene/1",
    "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0]},
    "medium": {"scattering": 0.1},
    "lights": [{"type": "spot", "position": [0, 3, 0], "direction": [0, -1, 0], "intensity": 10, "cone_deg": 30},
               {"type": "point", "position": [1, 3, 0], "intensity": 10}],
    "objects": [{"shape": "box", "min": [-1, -0.1, -1], "max": [1, 0, 1]}]})");
  const std::string out = " --size 32x24 --out " + (work_dir() / "limited.png").string();
  const std::string render = "render --scene " + scene.string() + out;
  const auto refusal = [&](const std::string& key, const std::string& counted, const std::string& method,
                           const std::string& why, const std::string& setting) {
    return "--set: " + key + ": the scene " + scene.string() + " has " + counted + ", more than " + method +
           " takes at this setting (" + why + "); a larger " + setting + " renders it anyway";
  };
  const std::string beam_why = "each light's beam tree holds every caster triangle and is built on the CPU every frame";
  const std::string plane_why = "each edge may be a shadow plane, and the planes are drawn across the image";
  expect_refused(render + " --method beam_volumes --set max_triangles=23",
                 refusal("max_triangles=23", "24 caster triangles summed over its lights", "beam_volumes", beam_why,
                         "max_triangles"));
  expect_refused(render + " --method shadow_planes --set max_edges=71",
                 refusal("max_edges=71", "72 caster triangle edges summed over its lights", "shadow_planes", plane_why,
                         "max_edges"));
  for (const std::string at :
       {" --method beam_volumes --set max_triangles=24", " --method shadow_planes --set max_edges=72"})
    EXPECT_EQ(run_airlight(render + at, no_gl()).status, 1) << at;
  // compare, bench and view check the same, compare and bench with the method's name in front.
  const std::string qualified = refusal("beam_volumes.max_triangles=23", "24 caster triangles summed over its lights",
                                        "beam_volumes", beam_why, "max_triangles");
  expect_refused("compare --scene " + scene.string() + " --methods raymarch,beam_volumes:max_triangles=23" + out,
                 qualified);
  expect_refused("bench --scene " + scene.string() + " --methods beam_volumes --set beam_volumes.max_triangles=23 "
                 "--sizes 32x24 --csv " + (work_dir() / "limited.csv").string(),
                 qualified);
  expect_refused("view --scene " + scene.string() + " --method beam_volumes --set max_triangles=23 --size 32x24",
                 refusal("max_triangles=23", "24 caster triangles summed over its lights", "beam_volumes", beam_why,
                         "max_triangles"));
  EXPECT_FALSE(fs::exists(work_dir() / "limited.png"));
  EXPECT_FALSE(fs::exists(work_dir() / "limited.csv"));
}

// One OpenGL object holds less than 4 GiB (a buffer) or 2 GiB (a texture) on
// Mesa, whatever the memory: refused up front too, as the no-GL environment shows.
TEST(OutputCheck, ObjectsBeyondOneOpenGlObjectExitTwoBeforeAnyOpenGl) {
  const std::string out = " --out " + (work_dir() / "big.png").string();
  const std::string plenty = no_gl() + " AIRLIGHT_MEMORY_MIB=1000000";
  expect_refused("render --builtin three_lights --method light_volume --set volume_resolution=2048 --set "
                 "shadow_resolution=2048 --size 64x48" + out,
                 "--set: volume_resolution=2048: light_volume needs 15.0 GiB in one OpenGL buffer for the light volume "
                 "meshes of 1 cube map (6 faces × 6·2048² triangles), 1 spot map (6·2048² triangles and the sides) "
                 "and 1 directional map (6·2048² triangles and the sides), 80 bytes a triangle, more than the 4.0 GiB "
                 "one buffer holds on Mesa",
                 plenty);
  // Two point lights' cubes share one texture array: 12 faces of 7000² floats.
  const fs::path scene = write_file("two_points.json", R"({"format": "airlight-scene/1",
    "camera": {"position": [0, 1, 5], "look_at": [0, 1, 0]}, "medium": {"scattering": 0.05},
    "lights": [{"type": "point", "position": [-1, 2, 0], "intensity": 10},
               {"type": "point", "position": [1, 2, 0], "intensity": 10}],
    "objects": [{"shape": "box", "min": [-2, 0, -2], "max": [2, 0.1, 2]}]})");
  expect_refused("render --scene " + scene.string() + " --method raymarch --set shadow_resolution=7000 --size 64x48" + out,
                 "--set: shadow_resolution=7000: raymarch needs 2.2 GiB in one OpenGL texture for the shadow maps of "
                 "2 lights (2 cubes of 6 faces, 7000² texels of 4 bytes each), more than the 2.0 GiB one texture holds "
                 "on Mesa",
                 plenty);
  expect_refused("render --builtin teapot_spot --method raymarch --size 12000x12000" + out,
                 "--size: 12000x12000: one RGBA float target of this size is 2.1 GiB, more than the 2.0 GiB one OpenGL "
                 "texture holds on Mesa",
                 plenty);
  EXPECT_FALSE(fs::exists(work_dir() / "big.png"));
}

// What the estimate misses still ends in a message, not a crash: with the
// address space capped below the mesh's buffer and the check told there is
// plenty, Mesa's GL_OUT_OF_MEMORY is reported in those words with the setting
// that sized the buffer, exit 1. (A sanitizer build reserves terabytes of
// address space up front and cannot start under such a cap: the control
// below tells which.)
TEST(OutputCheck, AnOutOfMemoryThatStillHappensNamesTheSetting) {
  const std::string cap = "ulimit -v 1100000; AIRLIGHT_MEMORY_MIB=1000000 ";
  const auto run = [&](const std::string& args) {
    const std::string command = cap + airlight_exe().string() + " " + args + " >/dev/null 2>" +
                                (work_dir() / "oom.txt").string();
    const int raw = std::system(command.c_str());  // sh -c: the cap holds for this command alone
    return Outcome{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, "", read_text(work_dir() / "oom.txt")};
  };
  if (run("list scenes").status != 0) GTEST_SKIP() << "this build cannot start in 1.1 GB of address space";
  // 6·2048² triangles of 80 bytes: a 1.9 GiB buffer (and their indices when drawn).
  const Outcome o = run("render --builtin teapot_spot --method light_volume --set volume_resolution=2048 --set "
                        "shadow_resolution=2048 --size 32x24 --out " + (work_dir() / "oom.pfm").string());
  EXPECT_EQ(o.status, 1) << o.err;
  EXPECT_EQ(o.err.rfind("airlight: failure: out of memory (GL_OUT_OF_MEMORY) in render:", 0), 0u) << o.err;
  EXPECT_NE(o.err.find("2.1 GiB of it for the light volume meshes of 1 spot map (6·2048² triangles and the sides), 80 "
                       "bytes a triangle: the setting most likely responsible is volume_resolution=2048"),
            std::string::npos)
      << o.err;
  EXPECT_FALSE(fs::exists(work_dir() / "oom.pfm"));
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
