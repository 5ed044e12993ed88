// `airlight compare` end to end (issue 6): the sheet, the CSV checked against
// the PFM outputs, the reference cache, and bad arguments.
#include "app/command_test_support.hpp"
#include "core/image_io.hpp"

#include <glm/common.hpp>

#include <algorithm>
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

// A spot in fog over a floor: a visible cone and a lit disc (the light itself
// above the frame).
const fs::path& scene_file() {
  static const fs::path file = [] {
    const fs::path f = work_dir() / "spot.json";
    std::ofstream(f) << R"({"format": "airlight-scene/1",
      "camera": {"position": [0, 2, 6], "look_at": [0, 1, 0]},
      "medium": {"scattering": 0.1},
      "lights": [{"type": "spot", "position": [0, 6, 0], "direction": [0, -1, 0], "intensity": 150, "cone_deg": 15}],
      "objects": [{"shape": "plane", "center": [0, 0, 0], "size": [8, 8], "normal": [0, 1, 0]}]})";
    return f;
  }();
  return file;
}

double rel_rmse(const Image& m, const Image& r) {
  double squared = 0.0, sum = 0.0;
  for (size_t i = 0; i < r.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      squared += std::pow(double(m.pixels[i][c]) - r.pixels[i][c], 2);
      sum += r.pixels[i][c];
    }
  const double n = 3.0 * r.pixels.size();
  return std::sqrt(squared / n) / (sum / n);
}

const std::vector<std::string> columns{"method",        "settings",       "width",     "height",   "pass",
                                       "rel_rmse",      "max_abs",        "psnr_db",   "mean_radiance",
                                       "reference_mean", "prepare_s",     "render_s",  "cached"};

TEST(Compare, WritesSheetAndCsvThatMatchThePfms) {
  const fs::path images = work_dir() / "images", csv = work_dir() / "errors.csv", sheet = work_dir() / "sheet.png";
  const std::string args = "compare --scene " + scene_file().string() +
                           " --methods 'reference,raymarch,raymarch:steps=8,planes' --size 64x48 --cache " +
                           (work_dir() / "cache").string() + " --images " + images.string() + " --csv " +
                           csv.string() + " --out " + sheet.string();
  const Outcome first = run(args);
  ASSERT_EQ(first.status, 0) << first.err;

  const Image png = read_image(sheet);
  EXPECT_GE(png.width, 5 * 128);   // five columns of 64×48 images shown at ×2
  EXPECT_GE(png.height, 2 * 96);   // the image and its heat map

  const auto rows = read_csv(csv);
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[0], columns);
  const std::vector<std::pair<std::string, std::string>> expected{
      {"reference", "reference.pfm"}, {"reference", "1_reference.pfm"}, {"raymarch", "2_raymarch.pfm"},
      {"raymarch", "3_raymarch.pfm"}, {"planes", "4_planes.pfm"}};
  const Image reference = read_image(images / "reference.pfm");
  for (size_t i = 0; i < expected.size(); ++i) {
    const auto& row = rows[i + 1];
    ASSERT_EQ(row.size(), columns.size()) << i;
    EXPECT_EQ(row[0], expected[i].first);
    EXPECT_EQ(row[2], "64");
    EXPECT_EQ(row[3], "48");
    EXPECT_EQ(row[4], "airlight");
    const double expected_rmse = rel_rmse(read_image(images / expected[i].second), reference);
    EXPECT_NEAR(std::stod(row[5]), expected_rmse, 1e-6 * expected_rmse + 1e-12) << row[0] << " " << row[1];
  }
  EXPECT_NE(rows[4][1].find("steps=8"), std::string::npos) << rows[4][1];
  EXPECT_EQ(rows[1][12], "0");  // rendered now

  // The heat maps' scale, printed: the 99th percentile (nearest rank) of the nonzero
  // errors, largest over RGB, of every image after the reference.
  std::vector<double> errors;
  for (size_t i = 1; i < expected.size(); ++i) {
    const Image image = read_image(images / expected[i].second);
    for (size_t p = 0; p < image.pixels.size(); ++p) {
      const glm::vec3 d = glm::abs(image.pixels[p] - reference.pixels[p]);
      if (const double e = std::max({d.r, d.g, d.b}); e > 0.0) errors.push_back(e);
    }
  }
  ASSERT_FALSE(errors.empty());
  std::sort(errors.begin(), errors.end());
  char line[256];
  std::snprintf(line, sizeof line,
                "compare: error maps' scale 0 to %.3g W/(m^2 sr): the 99th percentile of the nonzero errors; larger "
                "ones, up to %.3g, saturate\n",
                errors[static_cast<size_t>(std::ceil(0.99 * errors.size())) - 1], errors.back());
  EXPECT_NE(first.err.find(line), std::string::npos) << first.err;

  // The second run reads the reference from the cache: the CSV's `cached` column says so.
  const Outcome second = run(args);
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_EQ(read_csv(csv)[1][12], "1");
  EXPECT_NE(second.err.find("read from the cache"), std::string::npos) << second.err;
}

// Exit 2 and a message that starts with "<file>: <key>:" (InputError's form).
void expect_bad_options(const std::string& options, const std::string& file, const std::string& key) {
  expect_bad_input(run("compare --scene " + scene_file().string() + " --cache " + (work_dir() / "cache").string() +
                       " --out " + (work_dir() / "bad.png").string() + " " + options),
                   file, key, options);
}

TEST(Compare, BadArgumentsExitTwoNamingThem) {
  expect_bad_options("--methods raymarch,bogus", "--methods", "bogus");
  expect_bad_options("--methods 'raymarch:bogus=1'", "--methods", "bogus");
  expect_bad_options("--methods 'raymarch:steps=-3'", "--methods", "steps");
  expect_bad_options("--methods raymarch --set raymarch.bogus=1", "--set", "bogus");
  expect_bad_options("--methods raymarch --set planes.steps=1", "--set", "planes.steps");
  expect_bad_options("--methods raymarch,,planes", "--methods", "(empty entry)");
  expect_bad_options("--methods raymarch:", "--methods", "raymarch:");
  expect_bad_options("--methods raymarch --size 0x5", "--size", "0x5");
  EXPECT_EQ(run("compare --scene " + scene_file().string() + " --out x.png").status, 2);  // --methods is required
  expect_bad_options("--methods raymarch --exposure 0", "--exposure", "");
  // An unknown method lists the known ones, as render's --method does.
  EXPECT_EQ(run("compare --builtin teapot_spot --methods raymarch,bogus --out " + (work_dir() / "u.png").string()).err,
            "airlight: error: --methods: bogus: unknown method (known: reference, raymarch, interleaved, planes, analytic, "
            "shadow_planes, beam_volumes, hybrid_clip, hybrid, light_volume, sv_march)\n");
}

// `--csv -` (README "Pipes"): the same CSV on standard output, and nothing else there.
TEST(Compare, CsvDashWritesTheSameCsvToStandardOutput) {
  const fs::path csv = work_dir() / "piped.csv";
  const std::string args = "compare --scene " + scene_file().string() +
                           " --methods reference,raymarch:steps=8 --size 16x12" +
                           " --cache " + (work_dir() / "piped-cache").string() + " --out " +
                           (work_dir() / "piped.png").string() + " --csv ";
  const Outcome file = run(args + csv.string());
  ASSERT_EQ(file.status, 0) << file.err;
  EXPECT_EQ(file.out, "");
  const Outcome piped = run(args + "-");
  ASSERT_EQ(piped.status, 0) << piped.err;

  const Table written = read_csv(csv), printed = parse_csv(piped.out);
  ASSERT_EQ(printed.size(), 4u) << piped.out;  // the header, the cached reference, reference and raymarch
  EXPECT_EQ(printed[0], columns);
  // The first run rendered the reference into the cache, the second read it.
  EXPECT_EQ(written[1][column(written, "cached")], "0");
  EXPECT_EQ(printed[1][column(printed, "cached")], "1");
  const auto varies = [](const std::string& name) {
    return name == "prepare_s" || name == "render_s" || name == "cached";
  };
  EXPECT_EQ(without_columns(printed, varies), without_columns(written, varies));
}

}  // namespace
}  // namespace airlight
