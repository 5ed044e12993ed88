// `airlight bench` end to end: a tiny sweep's CSV, plot and equal-quality
// report, and its bad arguments (exit 2 naming the option and the key); and
// the own time and its ranking on constructed runs.
#include "app/bench_csv.hpp"
#include "app/bench_equal_quality.hpp"
#include "app/bench_timing.hpp"
#include "app/command_test_support.hpp"
#include "core/image_io.hpp"

#include <optional>

namespace airlight {
namespace {

using namespace test;

Outcome run(const std::string& args) {
  return run_airlight("bench " + args + " --cache " + (work_dir() / "cache").string());
}

// A spot light above the view, straight down past a small shelf onto a floor:
// nothing bright in view, no jitter, so the march's error falls as steps grow.
fs::path tiny_scene() {
  const fs::path file = work_dir() / "tiny.json";
  std::ofstream(file) << R"({"format": "airlight-scene/1",
    "camera": {"position": [0, 1.5, 6], "look_at": [0, 1.5, 0], "up": [0, 1, 0], "fov_y_deg": 40,
               "far": 30},
    "medium": {"scattering": 0.05, "absorption": 0.01, "phase": {"type": "isotropic"}},
    "lights": [{"type": "spot", "position": [0, 8, 0], "direction": [0, -1, 0], "intensity": 300,
                "cone_deg": 30}],
    "objects": [{"shape": "box", "min": [-0.5, 2.5, -0.5], "max": [0.5, 2.7, 0.5], "albedo": 0.5},
                {"shape": "plane", "center": [0, 0, 0], "size": [20, 20], "normal": [0, 1, 0], "albedo": 0.5}]})";
  return file;
}

TEST(Bench, RaymarchStepsSweepWritesFallingErrorPlotAndEqualQuality) {
  const fs::path csv = work_dir() / "sweep.csv", plot = work_dir() / "sweep.png";
  // Uniform steps, the documents' march: its error falls steadily with N.
  const Outcome o = run("--scene " + tiny_scene().string() +
                        " --methods raymarch --set raymarch.sampling=uniform --sweep raymarch.steps=4,16,64" +
                        " --sizes 64x48 --frames 2 --warmup 1 --csv " + csv.string() + " --plot " + plot.string() +
                        " --equal-quality 0.05");
  ASSERT_EQ(o.status, 0) << o.err;

  const Table rows = read_csv(csv);
  ASSERT_EQ(rows.size(), 4u);  // the header and one row per step count
  const size_t error = column(rows, "rel_rmse"), frame = column(rows, "frame_median_s"),
               airlight = column(rows, "airlight_median_s"), frames = column(rows, "frames");
  for (size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), rows[0].size());
    EXPECT_EQ(rows[i][frames], "2");
    EXPECT_GT(std::stod(rows[i][frame]), 0.0);
    EXPECT_GT(std::stod(rows[i][airlight]), 0.0);
    EXPECT_GT(std::stod(rows[i][column(rows, "gpu_mib")]), 0.0);
    EXPECT_LE(std::stod(rows[i][column(rows, "frame_min_s")]), std::stod(rows[i][frame]));
    // The median of two frames is their mean, which is linear: the median of
    // the frames' own-pass sums is the sum of the own passes' medians, up to
    // the CSV's 6 significant digits in each (5e-6 relative apiece).
    double own_passes = 0.0;
    for (size_t c = 0; c < rows[0].size(); ++c) {
      const std::string& name = rows[0][c];
      const std::string pass = name.substr(0, name.size() - std::string("_median_s").size());
      if (name.ends_with("_median_s") && name != "frame_median_s" && name != "own_median_s" && !rows[i][c].empty() &&
          !app::frame_pass(pass))
        own_passes += std::stod(rows[i][c]);
    }
    EXPECT_NEAR(std::stod(rows[i][column(rows, "own_median_s")]), own_passes, 2e-5 * own_passes);
    EXPECT_GT(own_passes, 0.0);
    if (i > 1) {
      EXPECT_LT(std::stod(rows[i][error]), std::stod(rows[i - 1][error])) << "steps row " << i;
    }
  }

  const Image image = read_image(plot);
  EXPECT_GE(image.width, 400);
  EXPECT_GE(image.height, 300);

  const Table equal = read_csv(work_dir() / "sweep-equal-quality.csv");
  ASSERT_EQ(equal.size(), 2u);
  EXPECT_EQ(equal[1][column(equal, "method")], "raymarch");
  EXPECT_DOUBLE_EQ(std::stod(equal[1][column(equal, "time_ratio")]), 1.0);
  EXPECT_NE(equal[1][column(equal, "settings")].find("steps=64"), std::string::npos);
  EXPECT_NE(o.out.find("raymarch"), std::string::npos) << o.out;  // the table on stdout
}

// Exit 2 and "airlight: error: <option>: <key>: ...".
void expect_bad_argument(const std::string& args, const std::string& option, const std::string& key) {
  expect_bad_input(run("--scene " + tiny_scene().string() + " --sizes 8x6 --csv " + (work_dir() / "bad.csv").string() +
                       " " + args),
                   option, key, args);
}

TEST(Bench, BadArgumentsExitTwoNamingOptionAndKey) {
  expect_bad_argument("--methods raymarch,nope", "--methods", "nope");
  expect_bad_argument("--methods raymarch --sweep raymarch.steps", "--sweep", "raymarch.steps");
  expect_bad_argument("--methods raymarch --sweep steps=1,2", "--sweep", "steps");
  expect_bad_argument("--methods raymarch --sweep raymarch.steps=a", "--sweep", "steps");
  expect_bad_argument("--methods raymarch --sweep raymarch.bogus=1,2", "--sweep", "bogus");
  expect_bad_argument("--methods raymarch --sweep planes.planes=15,30", "--sweep", "planes.planes");
  expect_bad_argument("--methods raymarch --set raymarch.bogus=1", "--set", "bogus");
  expect_bad_argument("--methods raymarch,planes --set steps=8", "--set", "steps");
  expect_bad_argument("--methods raymarch --sizes 0x5", "--sizes", "0x5");
  EXPECT_FALSE(fs::exists(work_dir() / "bad.csv"));  // nothing ran
  // Runs are counted before their settings are: 40 × 30 of them is over bench's 1000.
  std::string steps = "1", resolutions = "1";
  for (int i = 2; i <= 40; ++i) steps += "," + std::to_string(i);
  for (int i = 2; i <= 30; ++i) resolutions += "," + std::to_string(i);
  EXPECT_EQ(run("--builtin teapot_spot --methods raymarch --sweep raymarch.steps=" + steps +
                " --sweep raymarch.shadow_resolution=" + resolutions + " --csv " + (work_dir() / "r.csv").string()).err,
            "airlight: error: --sweep: raymarch.shadow_resolution: the sweeps of raymarch make more than 1000 runs\n");
  // An unknown method lists the known ones, as render's --method does.
  EXPECT_EQ(run("--builtin teapot_spot --methods raymarch,bogus --csv " + (work_dir() / "u.csv").string()).err,
            "airlight: error: --methods: bogus: unknown method (known: reference, raymarch, interleaved, planes, analytic, "
            "shadow_planes, beam_volumes, hybrid_clip, hybrid, light_volume, sv_march)\n");
}

// `--csv -` (README "Pipes"): the same CSV on standard output, and what bench
// prints beside it (the floor's times) on stderr instead.
TEST(Bench, CsvDashWritesTheSameCsvToStandardOutputAndTheReportToStderr) {
  const fs::path csv = work_dir() / "piped.csv";
  const std::string args = "--scene " + tiny_scene().string() +
                           " --methods raymarch --sweep raymarch.steps=4,8 --sizes 16x12 --frames 1 --warmup 0"
                           " --floor --csv ";
  const Outcome file = run(args + csv.string());
  ASSERT_EQ(file.status, 0) << file.err;
  EXPECT_EQ(file.out.rfind("floor 16x12: ", 0), 0u) << file.out;
  const Outcome piped = run(args + "-");
  ASSERT_EQ(piped.status, 0) << piped.err;
  EXPECT_NE(piped.err.find("floor 16x12: "), std::string::npos) << piped.err;

  const Table written = read_csv(csv), printed = parse_csv(piped.out);
  ASSERT_EQ(printed.size(), 3u) << piped.out;  // the header and a row per step count
  EXPECT_EQ(printed[0][0], "scene");
  // Times and the process's peak memory change from run to run; errors, GPU
  // memory and raymarch's stats (counters; planes' hold a time) do not.
  const auto varies = [](const std::string& name) {
    return name.ends_with("_s") || name == "ns_per_sample" || name == "floor_ratio" || name == "peak_rss_mib";
  };
  EXPECT_EQ(without_columns(printed, varies), without_columns(written, varies));
}

// The equal-quality table is written beside the CSV file; standard output is
// none, so the pair is refused before any work.
TEST(Bench, EqualQualityWithCsvDashIsRefused) {
  const Outcome o =
      run("--scene " + tiny_scene().string() + " --methods raymarch --sizes 16x12 --csv - --equal-quality 0.05");
  EXPECT_EQ(o.status, 2);
  EXPECT_EQ(o.err,
            "airlight: error: --equal-quality: --csv -: its table is written beside the CSV file, as "
            "FILE-equal-quality.csv, and standard output is no file: give --csv FILE\n");
  EXPECT_EQ(o.out, "");
}

// Own time is per frame summed, then the median over the frames — not the
// sum of each pass's median. Times are exact binary fractions: exact sums.
TEST(BenchOwnTime, IsTheMedianOverFramesOfEachFramesOwnPassSum) {
  const std::vector<std::vector<PassTime>> frames{
      {{"gbuffer", 1.0}, {"airlight", 1.0}, {"gather", 10.0}, {"readback", 0.5}},
      {{"gbuffer", 1.0}, {"airlight", 1.0}, {"airlight", 1.0}, {"gather", 2.0}},  // a pass twice: summed
      {{"gbuffer", 5.0}, {"shadow", 0.25}, {"airlight", 10.0}, {"gather", 1.0}}};
  app::Measurement m;
  app::summarize_passes(frames, &m);
  // Own sums 11, 4, 11: median 11; the passes' medians (airlight 2, gather 2) would sum to 4.
  ASSERT_TRUE(m.own_median_s);
  EXPECT_EQ(*m.own_median_s, 11.0);
  const std::vector<std::pair<std::string, double>> passes{
      {"gbuffer", 1.0}, {"airlight", 2.0}, {"gather", 2.0}, {"readback", 0.5}, {"shadow", 0.25}};
  EXPECT_EQ(m.pass_median_s, passes);

  app::Measurement reference;  // no own pass (the CPU reference): no own time, rather than 0
  app::summarize_passes({{{"readback", 0.5}}}, &reference);
  EXPECT_FALSE(reference.own_median_s);
}

app::Measurement measured(const std::string& method, const std::string& settings, double frame_s,
                     std::optional<double> own_s, double rel_rmse, bool baseline = false) {
  app::Measurement m;
  m.scene = "case";
  m.size = {64, 48};
  m.method = method;
  m.settings = settings;
  m.frame.median = frame_s;
  m.own_median_s = own_s;
  m.rel_rmse = rel_rmse;
  m.baseline = baseline;
  return m;
}

// Ranked by own time, the table picks other runs than by frame time, and
// each ratio is over the runs its own ranking picks.
TEST(BenchOwnTime, EqualQualityRanksByOwnTimeApartFromFrameTime) {
  const std::vector<app::Measurement> rows{
      measured("raymarch", "uniform", 1.0, 0.6, 0.01, true),  // brute force: the cheapest by own time
      measured("raymarch", "equiangular", 0.9, 0.7, 0.01),    // the cheapest raymarch by frame time
      measured("x", "a", 0.5, 0.4, 0.01),                     // x's cheapest frame
      measured("x", "b", 0.6, 0.1, 0.01),                     // x's cheapest own time
      measured("x", "c", 0.1, 0.05, 0.5),                     // cheaper still, but misses E
      measured("reference", "", 100.0, std::nullopt, 0.0)};   // no own passes
  const auto table = app::equal_quality_table(rows, 0.05, {"raymarch", "x", "reference"});
  ASSERT_EQ(table.size(), 4u);
  const auto cell = [&](size_t row, const std::string& name) {
    return table[row][static_cast<size_t>(std::find(table[0].begin(), table[0].end(), name) - table[0].begin())];
  };
  const auto number = [](double v) { return app::csv_number(v); };
  EXPECT_EQ(cell(1, "settings"), "equiangular");
  EXPECT_EQ(cell(1, "own_settings"), "uniform");
  EXPECT_EQ(cell(2, "settings"), "a");
  EXPECT_EQ(cell(2, "frame_median_s"), number(0.5));
  EXPECT_EQ(cell(2, "time_ratio"), number(0.5 / 1.0));       // over brute force's frame
  EXPECT_EQ(cell(2, "time_ratio_best"), number(0.5 / 0.9));  // over the equiangular run's frame
  EXPECT_EQ(cell(2, "own_settings"), "b");
  EXPECT_EQ(cell(2, "own_median_s"), number(0.1));
  EXPECT_EQ(cell(2, "own_rel_rmse"), number(0.01));
  EXPECT_EQ(cell(2, "own_ratio"), number(0.1 / 0.6));       // over brute force's own time
  EXPECT_EQ(cell(2, "own_ratio_best"), number(0.1 / 0.6));  // brute force is raymarch's cheapest by own time
  EXPECT_EQ(cell(3, "settings"), "");                       // the reference's run, by frame time
  EXPECT_EQ(cell(3, "frame_median_s"), number(100.0));
  EXPECT_EQ(cell(3, "own_median_s"), "");  // not ranked by own time
}

}  // namespace
}  // namespace airlight
