// `airlight bench` (issue 6): every method over scenes × sizes × setting sweeps,
// timed per frame and per pass, with its memory and its error against the
// cached reference; a CSV, optional log–log plots and an equal-quality table.
// Here the command's options and its runs; the plan, the timing, the CSV, the
// equal-quality table and the plots each have their file (bench_*.hpp).
#include "app/bench_csv.hpp"
#include "app/bench_equal_quality.hpp"
#include "app/bench_plan.hpp"
#include "app/bench_plots.hpp"
#include "app/bench_timing.hpp"
#include "app/commands.hpp"
#include "app/csv.hpp"
#include "app/floor.hpp"
#include "app/measure.hpp"
#include "app/output_check.hpp"
#include "reference/cache.hpp"
#include "core/atomic_file.hpp"
#include "core/metrics.hpp"
#include "gpu/gl.hpp"

#include <airlight/method.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>

namespace airlight::app {

namespace {

// Prepares the method, times its frames (the reference: no warm-up and one frame,
// it is slow and does not vary) and measures the last against `reference`.
Measurement measure(const Variant& variant, const Scene& scene, Size size, const Image& reference,
                    const BenchOptions& o) {
  const bool is_reference = variant.method->capabilities.ground_truth;
  Measurement m;
  m.scene = scene.name;
  m.method = variant.method->name;
  m.settings = variant.settings.describe();
  m.series = variant.series;
  m.size = size;
  m.frames = is_reference ? 1 : o.frames;
  m.baseline = m.method == "raymarch" && variant.settings.choice("jitter") == "none" &&
               variant.settings.choice("sampling") == "uniform";
  const double gpu_before = static_cast<double>(gpu::allocated_bytes());
  FrameImages last;
  with_memory_hint(scene, size, {variant.method, &variant.settings}, [&] {
    auto method = variant.method->create(variant.settings);
    method->prepare(scene);
    last = time_frames(*method, scene, size, is_reference ? 0 : o.warmup, m.frames, gpu_before, &m);
  });
  m.peak_rss_mib = peak_rss_mib();
  m.stats = last.stats;
  for (const auto& [name, value] : last.stats)
    if (name == "light_samples" || name == "fragments") m.samples = std::max(value, 0.0);
  const ImageError error = compare_images(last.airlight, reference);
  m.rel_rmse = error.rel_rmse;
  m.max_abs = error.max_abs;
  return m;
}

std::vector<Measurement> run_bench(const BenchOptions& o, const BenchPlan& plan) {
  const std::filesystem::path cache = o.cache.empty() ? reference::default_cache_dir() : std::filesystem::path(o.cache);
  std::vector<Measurement> rows;
  for (const auto& scene : plan.scenes)
    for (const auto& size : plan.sizes) {
      const Image expected = reference::cached_reference(scene, size.width, size.height, cache).airlight;
      double floor_ns = 0.0;
      if (o.floor) {
        const FloorTimes f = time_floor(size.width, size.height, o.warmup, o.frames);
        std::fprintf(report_stream(o.csv),
                     "floor %dx%d: full-screen pass %s s, march of %d steps %s s, %s ns per sample\n", size.width,
                     size.height, csv_number(f.fullscreen_s).c_str(), floor_steps, csv_number(f.march_s).c_str(),
                     csv_number(f.ns_per_sample).c_str());
        floor_ns = f.ns_per_sample;
      }
      for (const auto& variant : plan.variants) {
        rows.push_back(measure(variant, scene, size, expected, o));
        rows.back().floor_ns = floor_ns;
      }
    }
  return rows;
}

void bench(const BenchOptions& o) {
  const BenchPlan plan = plan_bench(o);
  const std::vector<Measurement> rows = run_bench(o, plan);
  OutputBatch outputs;
  write_measurements(o.csv, rows);
  if (!o.plot.empty()) write_plots(o.plot, rows);
  if (o.equal_quality > 0.0) write_equal_quality(rows, o.equal_quality, o.methods, o.csv);
  outputs.commit();
}

}  // namespace

Run add_bench_command(CLI::App& cli) {
  auto o = std::make_shared<BenchOptions>();
  auto* c = cli.add_subcommand("bench", "time methods over scenes, sizes and setting sweeps, with their error");
  c->add_option("--scene", o->scene_files, "scene file (repeatable)");
  c->add_option("--builtin", o->builtins, "built-in scene (repeatable; airlight list scenes)");
  c->add_option("--methods", o->methods, "methods to time, comma-separated (airlight list methods)")
      ->required()
      ->delimiter(',');
  c->add_option("--sweep", o->sweeps, "method.key=v1,v2,...: one run per value (repeatable; crossed per method)");
  c->add_option("--set", o->assignments, "method.key=value for every run of that method (repeatable)");
  c->add_option("--sizes", o->sizes, "image sizes WxH, comma-separated")->delimiter(',')->capture_default_str();
  c->add_option("--warmup", o->warmup, "untimed frames before the timed ones")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  c->add_option("--frames", o->frames, "timed frames per run")->check(CLI::Range(1, 10000))->capture_default_str();
  c->add_option("--csv", o->csv, "output: one row per scene, size, method and settings; -: standard output")
      ->required();
  c->add_option("--plot", o->plot, "output: rRMSE against frame time, log-log, per scene and size (PNG)");
  c->add_option("--equal-quality", o->equal_quality,
                "E: per method the cheapest run with rRMSE <= E, timed against brute-force raymarch")
      ->check(CLI::PositiveNumber);
  c->add_flag("--floor", o->floor,
              "time a minimal full-screen pass and a minimal march at each size (printed); ns_per_sample over "
              "the floor's is the CSV's floor_ratio");
  c->add_option("--cache", o->cache, "reference cache directory (default $AIRLIGHT_CACHE or ~/.cache/airlight)");
  return [o] { bench(*o); };
}

}  // namespace airlight::app
