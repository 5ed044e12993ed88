// The installed package end to end: `cmake --install` into a temporary prefix,
// examples/engine configured and built against it as an unrelated project
// would be, run, and its L_air held against `airlight render` of the same
// scene. The example draws its own depth (reversed-Z) and shadow maps (its own
// projection and bias), so agreement means the API converted the engine's
// conventions, not that it was handed airlight's own textures back.
#include "core/image_io.hpp"
#include "core/metrics.hpp"
#include "core/test_paths.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace airlight {
namespace {

namespace fs = std::filesystem;

// Per test process; kept when a step fails, to read its log.
const fs::path work = fs::temp_directory_path() / ("airlight_install_test_" + std::to_string(::getpid()));

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// Runs `command` with its output in work/<step>.log; unless it exits with
// `status`, returns the log.
::testing::AssertionResult step(const std::string& name, const std::string& command, int status = 0) {
  const fs::path log = work / (name + ".log");
  const int raw = std::system((command + " >" + quoted(log) + " 2>&1").c_str());
  if (WIFEXITED(raw) && WEXITSTATUS(raw) == status) return ::testing::AssertionSuccess();
  std::stringstream text;
  text << std::ifstream(log).rdbuf();
  return ::testing::AssertionFailure() << name << " did not exit " << status << ": " << command << "\n" << text.str();
}

TEST(Install, EngineExampleAgainstTheInstalledPackageMatchesRender) {
  fs::remove_all(work);
  fs::create_directories(work);
  const std::string cmake = quoted(AIRLIGHT_CMAKE), size = "128x96";
  const fs::path prefix = work / "prefix", build = work / "example";

  ASSERT_TRUE(step("install", cmake + " --install " + quoted(test::executable_dir() / AIRLIGHT_BUILD_FROM_TEST) + " --prefix " + quoted(prefix)));
  ASSERT_TRUE(step("configure", cmake + " -S " + quoted(test::source_dir() / "examples" / "engine") + " -B " + quoted(build) +
                                    " -G " + quoted(AIRLIGHT_GENERATOR) + " -DCMAKE_BUILD_TYPE=Release" +
                                    " -DCMAKE_CXX_COMPILER=" + quoted(AIRLIGHT_CXX) +
                                    " -DCMAKE_PREFIX_PATH=" + quoted(prefix)));
  ASSERT_TRUE(step("build", cmake + " --build " + quoted(build)));
  ASSERT_TRUE(step("example", quoted(build / "engine_example") + " --builtin teapot_spot --size " + size +
                                  " --set steps=256 --set sampling=equiangular --out-airlight " +
                                  quoted(work / "engine.pfm") + " --out-composite " + quoted(work / "composite.pfm")));
  // The library's InputError caught by type in the program (exit 2, not the
  // std::exception's 1): its type information is the library's exported one.
  ASSERT_TRUE(step("unknown_method", quoted(build / "engine_example") + " --method bogus --size 8x8 --out-airlight " +
                                         quoted(work / "bogus.pfm") + " --out-composite " + quoted(work / "bogus.pfm"),
                   2));
  ASSERT_TRUE(step("render", quoted(test::airlight_exe()) + " render --builtin teapot_spot --method raymarch --set steps=256"
                             " --set sampling=equiangular --pass airlight --size " + size + " --out " +
                             quoted(work / "render.pfm")));

  const Image engine = read_image(work / "engine.pfm"), composite = read_image(work / "composite.pfm");
  const Image reference = read_image(work / "render.pfm");
  // The same method and settings; only the shadow maps differ (the example's
  // resolution, projection and bias against airlight's own) and the depth's
  // round trip through reversed-Z, which move shadow edges in the beam by a
  // texel or so. A wrong conversion moves whole regions (depth) or the beam's
  // shadow (shadow maps) and lands far above this.
  constexpr double tolerance = 0.005;  // the shadow-edge texels of the example's own maps (docs/decisions.md)
  const ImageError error = compare_images(engine, reference);
  std::printf("engine example against render: rRMSE %.5f (bound %.3f), max abs %.4f\n", error.rel_rmse, tolerance,
              error.max_abs);
  EXPECT_LT(error.rel_rmse, tolerance) << "max abs " << error.max_abs << ", mean " << error.mean_reference;
  EXPECT_GT(error.mean_reference, 0.0);

  // The colour target became L_surf·T + L_air: never below L_air, above it on
  // the lit surfaces.
  ASSERT_EQ(composite.pixels.size(), engine.pixels.size());
  int brighter = 0;
  for (size_t i = 0; i < engine.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const float a = engine.pixels[i][c], l = composite.pixels[i][c];
      ASSERT_GE(l, a - 1e-3f * (1.0f + a)) << "pixel " << i;  // RGBA16F colour: half-float rounding
      brighter += l > a * 1.01f + 1e-4f;
    }
  EXPECT_GT(brighter, 0) << "no surface shading reached the composite";

  fs::remove_all(work);
}

}  // namespace
}  // namespace airlight
