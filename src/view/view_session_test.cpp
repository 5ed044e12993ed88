// `airlight view` end to end, under an Xvfb this test starts itself: a scripted
// session on teapot_spot that switches through every method, changes a setting
// through its widget, moves the camera and a light, edits the medium, saves a
// screenshot and the scene — and `airlight render` of the saved scene by the
// same method gives the screenshot again. Without a display the viewer exits 1
// saying how to run it.
#include "app/command_test_support.hpp"
#include "core/image_io.hpp"
#include "core/metrics.hpp"

#include <cmath>
#include <csignal>
#include <cstdlib>
#include <spawn.h>
#include <sstream>
#include <thread>

extern char** environ;

namespace airlight {
namespace {

using namespace test;

// An X server of our own on a free display number, gone when the test ends.
class Xvfb {
public:
  Xvfb() {
    const std::string binary = find_binary("Xvfb");
    if (binary.empty()) return;
    for (int n = 90 + ::getpid() % 50; n < 240 && pid_ <= 0; ++n)
      if (!fs::exists("/tmp/.X11-unix/X" + std::to_string(n)) && !fs::exists("/tmp/.X" + std::to_string(n) + "-lock"))
        start(binary, n);
  }
  ~Xvfb() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    ::waitpid(pid_, nullptr, 0);
  }
  bool installed() const { return installed_; }
  const std::string& display() const { return display_; }

private:
  std::string find_binary(const std::string& name) {
    std::stringstream path(std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin");
    for (std::string dir; std::getline(path, dir, ':');)
      if (fs::exists(fs::path(dir) / name)) {
        installed_ = true;
        return (fs::path(dir) / name).string();
      }
    return "";
  }

  // Started when its socket appears; a server that exits (the number was taken) leaves pid_ at 0.
  void start(const std::string& binary, int n) {
    const std::string display = ":" + std::to_string(n);
    std::vector<std::string> args{binary, display, "-screen", "0", "1280x800x24", "-nolisten", "tcp"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    if (posix_spawn(&pid, binary.c_str(), nullptr, nullptr, argv.data(), environ) != 0) return;
    for (int tries = 0; tries < 200; ++tries) {  // up to 10 s on a loaded machine
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      if (::waitpid(pid, nullptr, WNOHANG) == pid) return;
      if (fs::exists("/tmp/.X11-unix/X" + std::to_string(n))) {
        pid_ = pid;
        display_ = display;
        return;
      }
    }
    ::kill(pid, SIGTERM);
    ::waitpid(pid, nullptr, 0);
  }

  bool installed_ = false;
  pid_t pid_ = 0;
  std::string display_;
};

Xvfb& xvfb() {
  static Xvfb server;
  return server;
}

#define REQUIRE_XVFB()                                                                              \
  if (!xvfb().installed()) GTEST_SKIP() << "Xvfb is not installed (scripts/setup installs xvfb)"; \
  ASSERT_FALSE(xvfb().display().empty()) << "Xvfb did not start"

Outcome run_view(const std::string& script, const std::string& args) {
  const fs::path file = write_file("session.txt", script);
  return run_airlight("view --builtin teapot_spot --size 256x192 --script " + file.string() + " " + args,
                      "DISPLAY=" + xvfb().display());
}

double mean(const Image& image) {
  double sum = 0.0;
  for (const auto& p : image.pixels) sum += p.r + p.g + p.b;
  return sum / (3.0 * image.pixels.size());
}

bool finite(const Image& image) {
  for (const auto& p : image.pixels)
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b)) return false;
  return true;
}

TEST(ViewSession, ScriptedSessionSavesWhatRenderReproduces) {
  REQUIRE_XVFB();
  const fs::path dir = work_dir() / "session";
  fs::create_directories(dir / "saved");
  const auto methods = listed_methods(false);
  ASSERT_GE(methods.size(), 10u);
  std::string script = "frame\nscreenshot " + (dir / "steps64.exr").string() + "\n";
  script += "set steps 4\nframe\nscreenshot " + (dir / "steps4.exr").string() + "\n";
  for (const std::string& m : methods)
    script += "method " + m + "\nframe\nscreenshot " + (dir / (m + ".exr")).string() + "\n";
  script += "method raymarch\nset steps 32\n"
            "camera orbit 20 5\ncamera fly 0.2 0 0.5\n"
            "light 0 position -3.5 5.5 -0.8\nlight 0 cone 22\n"
            "medium scattering 0.08 0.08 0.08\n"
            "frame 2\n"
            "screenshot " + (dir / "final.exr").string() + "\nscreenshot " + (dir / "final.png").string() +
            "\nsave " + (dir / "saved" / "scene.json").string() + "\nquit\n";
  const Outcome o = run_view(script, "");
  ASSERT_EQ(o.status, 0) << o.err;

  // A setting changed through its widget changes the image: 4 steps against 64.
  const ImageError steps = compare_images(read_image(dir / "steps4.exr"), read_image(dir / "steps64.exr"));
  std::printf("steps=4 against steps=64: rRMSE %.4f\n", steps.rel_rmse);
  EXPECT_GT(steps.rel_rmse, 0.01);

  for (const std::string& m : methods) {  // every method showed the lit scene
    const Image image = read_image(dir / (m + ".exr"));
    EXPECT_TRUE(finite(image)) << m;
    EXPECT_GT(mean(image), 0.0) << m;
  }
  EXPECT_TRUE(fs::exists(dir / "final.png"));

  // The saved scene renders to the screenshot: the same method, settings and
  // inputs on the same llvmpipe. The scene's floats are written exactly; its
  // meshes come back from OBJ with their vertices renumbered and their normals
  // renormalized (an ulp), which moves a few pixels by float rounding: measured
  // rRMSE 1e-6; 1e-4 would still catch any pose, light or medium not saved.
  const Outcome r = run_airlight("render --scene " + (dir / "saved" / "scene.json").string() +
                                 " --method raymarch --set steps=32 --size 256x192 --out " +
                                 (dir / "render.exr").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const ImageError e = compare_images(read_image(dir / "final.exr"), read_image(dir / "render.exr"));
  std::printf("viewer screenshot against airlight render of the saved scene: rRMSE %.6f, max abs %.6f\n",
              e.rel_rmse, e.max_abs);
  EXPECT_LT(e.rel_rmse, 1e-4);
  // The edits are in the file and the image: not the scene as built in.
  const ImageError moved = compare_images(read_image(dir / "final.exr"), read_image(dir / "raymarch.exr"));
  EXPECT_GT(moved.rel_rmse, 0.05);
}

// The error view: the reference renders in the background and the method's
// error against it is measured again when a setting changes. raymarch at its
// defaults misses the reference's composite by a few per cent here (the floor's
// 1024² shadow-map edges, 64 samples); 4 samples are clearly worse.
TEST(ViewSession, ErrorAgainstTheBackgroundReference) {
  REQUIRE_XVFB();
  const fs::path script = write_file("error.txt", "error heat\nreference\nset steps 4\nreference\nquit\n");
  const Outcome o = run_airlight("view --builtin teapot_spot --size 96x72 --script " + script.string(),
                                 "DISPLAY=" + xvfb().display());
  ASSERT_EQ(o.status, 0) << o.err;
  double defaults = 0.0, few = 0.0;
  ASSERT_EQ(std::sscanf(o.out.c_str(), "raymarch: rRMSE %lf against the reference\nraymarch: rRMSE %lf", &defaults, &few),
            2)
      << o.out;
  std::printf("rRMSE against the reference: steps=64 %.4f, steps=4 %.4f\n", defaults, few);
  EXPECT_LT(defaults, 0.1);
  EXPECT_GT(few, defaults);
}

// A scene without lights (every glTF model without KHR_lights_punctual) opens
// and shows its surfaces, lit by the ambient term alone, in every method.
TEST(ViewSession, SceneWithoutLightsShowsItsSurfaces) {
  REQUIRE_XVFB();
  const fs::path scene = write_file("no_lights.json", R"({"format": "airlight-scene/1", "ambient": 0.5,
      "medium": {"scattering": 0.05}, "objects": [{"shape": "box", "min": [-2, 0, -2], "max": [2, 1, 2]}]})");
  const auto methods = listed_methods(false);
  std::string script;
  for (const std::string& m : methods)
    script += "method " + m + "\nframe\nscreenshot " + (work_dir() / ("no_lights_" + m + ".exr")).string() + "\n";
  const fs::path file = write_file("no_lights.txt", script + "quit\n");
  // Mesa's shader cache off: the defects of a scene without lights showed only when compiling.
  const Outcome o = run_airlight("view --scene " + scene.string() + " --size 64x48 --script " + file.string(),
                                 "DISPLAY=" + xvfb().display() + " MESA_SHADER_CACHE_DISABLE=true");
  ASSERT_EQ(o.status, 0) << o.err;
  for (const std::string& m : methods) {
    const Image image = read_image(work_dir() / ("no_lights_" + m + ".exr"));
    EXPECT_TRUE(finite(image)) << m;
    EXPECT_GT(mean(image), 0.0) << m;
  }
}

// Progressive rendering: full size at rest, half size (the default moving
// scale) while the camera orbits.
TEST(ViewSession, ReducedSizeWhileTheCameraMoves) {
  REQUIRE_XVFB();
  const Outcome o = run_view("measure 3\nquit\n", "");
  ASSERT_EQ(o.status, 0) << o.err;
  EXPECT_NE(o.out.find("at 256x192, moving"), std::string::npos) << o.out;
  EXPECT_NE(o.out.find("at 128x96\n"), std::string::npos) << o.out;
}

TEST(ViewSession, ScriptErrorsNameTheLine) {
  REQUIRE_XVFB();
  const Outcome o = run_view("frame\ncamera spin 3\n", "");
  expect_bad_input(o, (work_dir() / "session.txt").string(), "line 2", "a bad script line");
  const Outcome s = run_view("set no_such_setting 3\n", "");
  expect_bad_input(s, "set", "no_such_setting", "an unknown widget label");
  const Outcome l = run_view("light 1 cone 20\n", "");  // teapot_spot has one light
  expect_bad_input(l, (work_dir() / "session.txt").string(), "line 1", "a light the scene does not have");
  const Outcome r = run_view("method reference\n", "");
  expect_bad_input(r, "method", "reference", "the CPU reference is not a live method");
  // A method's limit holds at each change in the viewer as at the command line
  // (OutputCheck.ScenesBeyondAMethodsLimitExitTwoBeforeAnyOpenGl has the whole message).
  const Outcome b = run_view("method beam_volumes\nset max_triangles 10\nquit\n", "");
  expect_bad_input(b, "--set", "max_triangles=10", "a scene beyond beam_volumes' triangle limit");
  EXPECT_NE(b.err.find("a larger max_triangles renders it anyway"), std::string::npos) << b.err;
}

// No window without a display: exit 1, saying how to run it under Xvfb.
void expect_no_display(const std::string& env) {
  const Outcome o = run_airlight("view --builtin teapot_spot", env);
  EXPECT_EQ(o.status, 1) << env << ": " << o.err;
  EXPECT_NE(o.err.find("no display"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("xvfb-run -s \"-screen 0 1280x800x24\" airlight view"), std::string::npos) << o.err;
}

TEST(ViewNoDisplay, UnsetDisplayExitsOneWithTheXvfbHint) { expect_no_display("-u DISPLAY -u WAYLAND_DISPLAY"); }

TEST(ViewNoDisplay, DeadDisplayExitsOneWithTheXvfbHint) { expect_no_display("-u WAYLAND_DISPLAY DISPLAY=:239"); }

}  // namespace
}  // namespace airlight
