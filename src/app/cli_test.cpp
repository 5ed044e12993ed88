// The `airlight` command end to end: exit statuses and messages (docs/design.md §5).
#include "app/command_test_support.hpp"
#include "core/image_io.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace airlight {
namespace {

using namespace test;

Outcome run(const std::string& args) { return run_airlight(args); }
Outcome run_with_env(const std::string& env, const std::string& args) { return run_airlight(args, env); }

// Exit 2 and a message that starts with "<file>: <key>:" (InputError's form).
void expect_bad_input(const std::string& args, const std::string& file, const std::string& key) {
  test::expect_bad_input(run(args), file, key, args);
}

// Exit 2 and exactly "airlight: error: <message>" on stderr, nothing more.
void expect_error(const std::string& args, const std::string& message) {
  const Outcome o = run(args);
  EXPECT_EQ(o.status, 2) << args;
  EXPECT_EQ(o.err, "airlight: error: " + message + "\n") << args;
}

const std::string header = R"("format": "airlight-scene/1")";

// A scene with `body` after the format key, rendered; expects exit 2 naming `key`.
void expect_bad_scene(const std::string& name, const std::string& body, const std::string& key) {
  const fs::path file = write_file(name + ".json", "{" + header + (body.empty() ? "" : ", " + body) + "}");
  expect_bad_input("render --scene " + file.string() + " --size 8x6 --out " + (work_dir() / "x.pfm").string(),
                   file.string(), key);
}

TEST(Cli, BadScenesExitTwoNamingFileAndKey) {
  expect_bad_scene("unknown_key", R"("camera": {"positon": [0, 1, 2]})", "camera.positon");
  expect_bad_scene("wrong_type", R"("camera": {"fov_y_deg": "wide"})", "camera.fov_y_deg");
  expect_bad_scene("non_finite", R"("medium": {"scattering": 1e999})", "medium.scattering");
  expect_bad_scene("negative", R"("medium": {"absorption": -0.1})", "medium.absorption");
  expect_bad_scene("out_of_range", R"("lights": [{"type": "spot", "position": [0, 5, 0],
      "direction": [0, -1, 0], "intensity": 1, "cone_deg": 200}])", "lights[0].cone_deg");
  expect_bad_scene("zero_vector", R"("lights": [{"type": "directional", "direction": [0, 0, 0],
      "irradiance": 1}])", "lights[0].direction");
  expect_bad_scene("missing_mesh", R"("objects": [{"mesh": "nowhere.obj"}])", "objects[0].mesh");
  expect_bad_scene("missing_gobo", R"("lights": [{"type": "spot", "position": [0, 5, 0],
      "direction": [0, -1, 0], "intensity": 1, "cone_deg": 20, "gobo": "nowhere.png"}])", "lights[0].gobo");
  expect_bad_scene("phase_g", R"("medium": {"phase": {"type": "henyey_greenstein", "g": 1.5}})", "medium.phase.g");
}

// The README's example line, word for word.
TEST(Cli, OutOfRangeSaysTheRangeAndTheValue) {
  const fs::path file = write_file("cone.json", "{" + header + R"(, "lights": [{"type": "point", "position": [0, 5, 0],
      "intensity": 1}, {"type": "spot", "position": [0, 5, 0], "direction": [0, -1, 0], "intensity": 1,
      "cone_deg": 200}]})");
  expect_error("render --scene " + file.string() + " --size 8x6 --out " + (work_dir() / "x.pfm").string(),
               file.string() + ": lights[1].cone_deg: must be in (0, 180], got 200");
}

// A gobo that is no image, or one cut short: the light, the file and what is wrong in words.
TEST(Cli, CorruptGoboNamesTheLightTheFileAndTheFault) {
  const fs::path good = work_dir() / "good_gobo.png";
  Image noise(64, 64);  // varied, so that half the file ends inside the pixel data
  for (size_t i = 0; i < noise.pixels.size(); ++i) noise.pixels[i] = glm::vec3(float(i * 37 % 251) / 251.0f);
  write_image(noise, good);
  const std::string png = read_text(good);
  const struct {
    const char* name;
    std::string bytes, fault;
  } cases[] = {{"text_gobo.png", "not an image\n", "not a PNG image (the file is damaged or another format)"},
               {"cut_gobo.png", png.substr(0, png.size() / 2), "the file is cut short"}};
  for (const auto& c : cases) {
    const fs::path gobo = write_file(c.name, c.bytes);
    const fs::path scene = write_file("gobo.json", "{" + header + R"(, "lights": [{"type": "spot", "position": [0, 5, 0],
        "direction": [0, -1, 0], "intensity": 1, "cone_deg": 20, "gobo": ")" + std::string(c.name) + "\"}]}");
    expect_error("render --scene " + scene.string() + " --size 8x6 --out " + (work_dir() / "x.pfm").string(),
                 scene.string() + ": lights[0].gobo: cannot read " + gobo.string() + ": " + c.fault);
  }
}

TEST(Cli, MalformedJsonAndMissingFilesNameTheFile) {
  const fs::path broken = write_file("broken.json", "{" + header + ", \"camera\": {");
  const Outcome o = run("render --scene " + broken.string() + " --out x.pfm");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err.rfind("airlight: error: " + broken.string() + ": ", 0), 0u) << o.err;
  const fs::path missing = work_dir() / "missing.json";
  const Outcome m = run("render --scene " + missing.string() + " --out x.pfm");
  EXPECT_EQ(m.status, 2);
  EXPECT_EQ(m.err.rfind("airlight: error: " + missing.string() + ": ", 0), 0u) << m.err;
}

TEST(Cli, DegenerateTrianglesInAnObjAreSkippedWithAWarning) {
  const fs::path obj = write_file("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 4\nf 1 2 3\nf 4 4 1\n");
  const fs::path scene = write_file("flat.json", "{" + header + R"(, "objects": [{"mesh": "flat.obj"}]})");
  const Outcome o = run("render --scene " + scene.string() + " --size 8x6 --out " + (work_dir() / "flat.pfm").string());
  EXPECT_EQ(o.status, 0) << o.err;
  EXPECT_EQ(o.err, "airlight: warning: " + obj.string() + ": skipped 2 degenerate triangles (zero area)\n");
}

// glTF scenes fail the same way, naming the glTF element (docs/scene-format.md "glTF scenes").
TEST(Cli, MalformedGltfExitsTwoNamingFileAndElement) {
  const fs::path gltf = write_file("no_position.gltf", R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {}}]}]})");
  expect_bad_input("render --scene " + gltf.string() + " --size 8x6 --out " + (work_dir() / "x.pfm").string(),
                   gltf.string(), "meshes[0].primitives[0]");
}

TEST(Cli, BadOptionsExitTwoNamingTheOption) {
  const std::string out = " --out " + (work_dir() / "x.pfm").string();
  expect_error("render --builtin no_such_scene" + out,
               "--builtin: no_such_scene: unknown built-in scene (known: biri_media, biri_pens, biri_sphere, "
               "nilsson_multiple, nilsson_parallel, nilsson_toplight, stage, stained_glass, teapot_spot, "
               "three_lights, toth_hall)");
  expect_bad_input("render --builtin teapot_spot --method no_such_method" + out, "--method", "no_such_method");
  expect_bad_input("render --builtin teapot_spot --set rel_tol=-1" + out, "--set", "rel_tol");
  expect_bad_input("render --builtin teapot_spot --set raymarch.steps=4" + out, "--set", "raymarch.steps");
  expect_bad_input("render --builtin teapot_spot --set bogus=1" + out, "--set", "bogus");
  expect_bad_input("render --builtin teapot_spot --size 0x5" + out, "--size", "0x5");
  expect_bad_input("render --builtin teapot_spot --size 8x6 --out x.bmp", "--out", "x.bmp");
  EXPECT_EQ(run("render --builtin teapot_spot").status, 2);     // --out is required
  EXPECT_EQ(run("render --size 8x6" + out).status, 2);          // no scene
  EXPECT_EQ(run("list colours").status, 2);
}

TEST(Cli, ExposureIsAPositiveNumberOrAuto) {
  const std::string render = "render --builtin teapot_spot --size 8x6 --out " + (work_dir() / "x.png").string();
  for (const std::string bad : {"x", "0", "-2", "nan", "inf", "2x"}) {
    const Outcome o = run(render + " --exposure=" + bad);  // '=': CLI11 would read " -2" as an option
    EXPECT_EQ(o.status, 2) << bad;
    EXPECT_EQ(o.err, "airlight: error: --exposure: must be a positive number or auto, got '" + bad + "'\n");
  }
  EXPECT_EQ(run(render + " --tonemap filmic").status, 2);
}

// What CLI11 rejects reads as every other error, then says where the usage is; an unknown
// argument is named before a required option it may be the misspelling of.
TEST(Cli, CommandLineErrorsHaveTheErrorPrefixAndAHint) {
  const std::string render_hint = "run 'airlight render --help' for usage\n";
  const Outcome missing_value = run("render --builtin teapot_spot --size");
  EXPECT_EQ(missing_value.status, 2);
  EXPECT_EQ(missing_value.err, "airlight: error: --size: 1 required TEXT missing\n" + render_hint);
  const Outcome misspelt = run("render --builtin teapot_spot --ot x.pfm");
  EXPECT_EQ(misspelt.status, 2);
  EXPECT_EQ(misspelt.err, "airlight: error: unknown arguments: --ot x.pfm\n" + render_hint);
  const Outcome command = run("frobnicate");
  EXPECT_EQ(command.status, 2);
  EXPECT_EQ(command.err, "airlight: error: unknown argument: frobnicate\nrun 'airlight --help' for usage\n");
  const Outcome help = run("render --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("--scene"), std::string::npos) << help.out;
}

// Without a usable OpenGL driver a GPU method fails with exit 1 and says what to
// install. Two ways to lose the driver: Mesa finds no DRI driver, or libglvnd
// finds no EGL vendor at all.
TEST(Cli, NoOpenGlContextExitsOneSayingWhatToInstall) {
  const std::string args = "render --builtin teapot_spot --method raymarch --size 8x6 --out " +
                           (work_dir() / "gl.pfm").string();
  for (const char* env : {"LIBGL_DRIVERS_PATH=/nonexistent", "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json"}) {
    const Outcome o = run_with_env(env, args);
    EXPECT_EQ(o.status, 1) << env << "\n" << o.err;
    EXPECT_NE(o.err.find("no OpenGL 4.5 core context"), std::string::npos) << env << "\n" << o.err;
    EXPECT_NE(o.err.find("apt-get install"), std::string::npos) << env << "\n" << o.err;
  }
}

TEST(Cli, ListNamesMethodsAndScenes) {
  EXPECT_EQ(run("list methods").status, 0);
  EXPECT_EQ(run("list scenes").status, 0);
  EXPECT_EQ(run("--help").status, 0);
}

// Each setting with its values and default in columns aligned within its method.
TEST(Cli, ListMethodsGivesEachSettingsRangeAndDefault) {
  const Outcome o = run("list methods");
  ASSERT_EQ(o.status, 0) << o.err;
  for (const char* line :
       {"\n    rel_tol       (number in [1e-07, 0.1], default 0.001)  relative accuracy of each pixel's airlight integral\n",
        "\n    min_segments  (integer in [1, 4096], default 128)      initial panels per ray",
        "\n    jitter             (one of: none, white, blue; default none)            per-pixel offset",
        "\n    depth_aware        (true or false, default true)                        move each pixel's"})
    EXPECT_NE(o.out.find(line), std::string::npos) << line << "\nnot in:\n" << o.out;
}

// A small render writes finite values and a report that describes them.
TEST(Cli, RenderWritesImageAndReport) {
  const fs::path image = work_dir() / "a.pfm", report = work_dir() / "a.json";
  const Outcome o = run("render --builtin teapot_spot --pass airlight --size 32x24 --out " + image.string() +
                        " --report " + report.string() + " --tonemap aces --exposure auto");
  ASSERT_EQ(o.status, 0) << o.err;
  const Image a = read_image(image);
  ASSERT_EQ(a.width, 32);
  ASSERT_EQ(a.height, 24);
  double max_value = 0.0;
  for (const auto& p : a.pixels)
    for (int c = 0; c < 3; ++c) {
      ASSERT_TRUE(std::isfinite(p[c]));
      ASSERT_GE(p[c], 0.0f);
      max_value = std::max<double>(max_value, p[c]);
    }
  EXPECT_GT(max_value, 0.0);  // the shaft is visible: not a silent black image
  const nlohmann::json r = nlohmann::json::parse(std::ifstream(report));
  EXPECT_EQ(r["method"], "reference");
  EXPECT_EQ(r["size"], nlohmann::json::array({32, 24}));
  EXPECT_EQ(r["pass"], "airlight");
  EXPECT_FLOAT_EQ(r["output"]["max"][0].get<float>(), [&] {
    float m = 0;
    for (const auto& p : a.pixels) m = std::max(m, p.r);
    return m;
  }());
  EXPECT_GT(r["stats"]["shadow_rays"].get<double>(), 0.0);
  EXPECT_GT(r["timings"]["render_s"].get<double>(), 0.0);
  // The exposure PNG output would use, measured on the image; 1e-6 relative: float sums.
  EXPECT_EQ(r["tonemap"]["curve"], "aces");
  EXPECT_EQ(r["tonemap"]["auto"], true);
  EXPECT_NEAR(r["tonemap"]["exposure"].get<double>(), auto_exposure(a), 1e-6 * auto_exposure(a));
  char printed[64];
  std::snprintf(printed, sizeof printed, "render: --exposure auto: %.4g\n", auto_exposure(a));
  EXPECT_NE(o.err.find(printed), std::string::npos) << o.err;
}

}  // namespace
}  // namespace airlight
