// `airlight compare` end to end (issue 6): the sheet, the CSV checked against
// the PFM outputs, the reference cache, and bad arguments.
#include "core/image_io.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace airlight {
namespace {

namespace fs = std::filesystem;

const fs::path& work_dir() {
  static const fs::path dir = [] {
    fs::path d = fs::temp_directory_path() / ("airlight_compare_test_" + std::to_string(::getpid()));
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

// Each test process removes its directory, caches included, when it ends.
class RemoveWorkDir : public ::testing::Environment {
  void TearDown() override { fs::remove_all(work_dir()); }
};
const auto* const remove_work_dir = ::testing::AddGlobalTestEnvironment(new RemoveWorkDir);

struct Outcome {
  int status = -1;
  std::string err;
};

Outcome run(const std::string& args) {
  const fs::path err = work_dir() / "stderr.txt";
  const std::string command = std::string(AIRLIGHT_EXE) + " " + args + " >/dev/null 2>" + err.string();
  const int raw = std::system(command.c_str());
  std::stringstream text;
  text << std::ifstream(err).rdbuf();
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text.str()};
}

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

std::vector<std::vector<std::string>> read_csv(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) fields.push_back(cell);
    rows.push_back(fields);
  }
  return rows;
}

// DESIGN §6 written out again, independently of core/metrics.
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

  // The second run reads the reference from the cache: the CSV's `cached` column says so.
  const Outcome second = run(args);
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_EQ(read_csv(csv)[1][12], "1");
  EXPECT_NE(second.err.find("read from the cache"), std::string::npos) << second.err;
}

// Exit 2 and a message that starts with "<file>: <key>:" (InputError's form).
void expect_bad_input(const std::string& options, const std::string& file, const std::string& key) {
  const Outcome o = run("compare --scene " + scene_file().string() + " --cache " +
                        (work_dir() / "cache").string() + " --out " + (work_dir() / "bad.png").string() + " " + options);
  EXPECT_EQ(o.status, 2) << options << "\n" << o.err;
  const std::string prefix = "airlight: error: " + file + ": " + key + ": ";
  EXPECT_EQ(o.err.rfind(prefix, 0), 0u) << "expected a message starting with '" << prefix << "', got: " << o.err;
}

TEST(Compare, BadArgumentsExitTwoNamingThem) {
  expect_bad_input("--methods raymarch,bogus", "--methods", "bogus");
  expect_bad_input("--methods 'raymarch:bogus=1'", "--methods", "bogus");
  expect_bad_input("--methods 'raymarch:steps=-3'", "--methods", "steps");
  expect_bad_input("--methods raymarch --set raymarch.bogus=1", "--set", "bogus");
  expect_bad_input("--methods raymarch --set planes.steps=1", "--set", "planes.steps");
  expect_bad_input("--methods raymarch,,planes", "--methods", "(empty entry)");
  expect_bad_input("--methods raymarch:", "--methods", "raymarch:");
  expect_bad_input("--methods raymarch --size 0x5", "command line", "--size");
  EXPECT_EQ(run("compare --scene " + scene_file().string() + " --out x.png").status, 2);  // --methods is required
}

}  // namespace
}  // namespace airlight
