// `airlight bench` (issue 6): every method over scenes × sizes × setting sweeps,
// timed per frame and per pass, with its memory and its error against the
// cached reference; a CSV, optional log–log plots and an equal-quality table.
#include "app/commands.hpp"
#include "app/csv.hpp"
#include "app/floor.hpp"
#include "app/measure.hpp"
#include "app/method_settings.hpp"
#include "app/output_check.hpp"
#include "app/plot.hpp"
#include "reference/cache.hpp"
#include "app/scene_source.hpp"
#include "core/atomic_file.hpp"
#include "core/metrics.hpp"
#include "core/progress.hpp"
#include "gpu/gl.hpp"

#include <airlight/error.hpp>
#include <airlight/method.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <memory>

namespace airlight::app {

namespace {

struct BenchOptions {
  std::vector<std::string> scene_files, builtins, methods, sweeps, assignments, sizes{"256x192"};
  std::string csv, plot, cache;
  int warmup = 1, frames = 5;
  double equal_quality = 0.0;  // 0: no equal-quality report
  bool floor = false;          // time the floor (floor.hpp) at each size
};

struct Spread {
  double median = 0.0, min = 0.0, max = 0.0;
};

// One CSV row.
struct Measurement {
  std::string scene, method, settings, series;
  Size size;
  int frames = 0;
  Spread frame;
  std::vector<std::pair<std::string, double>> pass_median_s;  // in the order the frame runs them
  double gpu_mib = 0.0, peak_rss_mib = 0.0, rel_rmse = 0.0, max_abs = 0.0;
  bool baseline = false;  // raymarch, uniform steps without jitter: brute force, the equal-quality yardstick
  double samples = 0.0;   // light samples (marches) or fragments (planes) of a frame; 0: not a sampling method
  double method_s = 0.0;  // the median seconds of the method's own passes (all but the shared frame's)
  double floor_ns = 0.0;  // the floor's ns per sample at this size; 0: not timed
  double first_frame_s = 0.0;  // the first frame: it compiles the programs of a new define set
  std::vector<std::pair<std::string, double>> stats;  // the method's counters of the last frame
};

// The shared frame's passes; every other pass is the method's own.
bool frame_pass(const std::string& pass) {
  return pass == "gbuffer" || pass == "depth" || pass == "shadow" || pass == "surface" || pass == "engine" ||
         pass == "readback";
}

std::vector<Scene> load_scenes(const BenchOptions& o) {
  if (o.scene_files.empty() && o.builtins.empty())
    throw InputError("--scene", "", "give --scene FILE or --builtin NAME (repeatable)");
  std::vector<Scene> scenes;
  for (const auto& file : o.scene_files) scenes.push_back(load_scene(file));
  for (const auto& name : o.builtins) scenes.push_back(builtin_scene(name));
  return scenes;
}

Spread spread(const std::vector<double>& values) {
  return {median(values), *std::min_element(values.begin(), values.end()),
          *std::max_element(values.begin(), values.end())};
}

// The value under `name` in a list kept in first-seen order, appended when absent.
template <typename T>
T& entry(std::vector<std::pair<std::string, T>>& list, const std::string& name) {
  const auto it = std::find_if(list.begin(), list.end(), [&](const auto& p) { return p.first == name; });
  return it != list.end() ? it->second : list.emplace_back(name, T{}).second;
}

// Appends one frame's seconds per pass; a pass run several times in a frame
// counts once, summed.
void add_pass_times(const std::vector<PassTime>& times,
                    std::vector<std::pair<std::string, std::vector<double>>>* pass_s) {
  std::vector<std::pair<std::string, double>> frame;
  for (const auto& t : times) entry(frame, t.pass) += t.seconds;
  for (const auto& [pass, seconds] : frame) entry(*pass_s, pass).push_back(seconds);
}

// Renders W warm-up frames and F timed ones into `m` (times, GPU memory of the
// first frame over `gpu_before`); returns the last frame.
FrameImages time_frames(Method& method, const Scene& scene, Size size, int warmup, int frames, double gpu_before, Measurement* m) {
  Progress progress(m->scene + " " + std::to_string(size.width) + "x" + std::to_string(size.height) + " " +
                        m->method + " " + m->settings,
                    warmup + frames);
  std::vector<double> frame_s;
  std::vector<std::pair<std::string, std::vector<double>>> pass_s;
  FrameImages frame;
  for (int i = 0; i < warmup + frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    frame = render(method, scene, size.width, size.height, false);  // bench measures L_air alone
    const double seconds = seconds_since(start);
    if (i == 0) {
      m->gpu_mib = (static_cast<double>(gpu::allocated_bytes()) - gpu_before) / (1 << 20);
      m->first_frame_s = seconds;
    }
    progress.advance();
    if (i < warmup) continue;
    frame_s.push_back(seconds);
    std::vector<PassTime> times = frame.times;
    if (frame.readback_s > 0.0) times.push_back({"readback", frame.readback_s});  // part of the frame's time
    add_pass_times(times, &pass_s);
  }
  m->frame = spread(frame_s);
  for (const auto& [pass, s] : pass_s) m->pass_median_s.emplace_back(pass, median(s));
  return frame;
}

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

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
  for (const auto& [pass, seconds] : m.pass_median_s)
    if (!frame_pass(pass)) m.method_s += seconds;
  const ImageError error = compare_images(last.airlight, reference);
  m.rel_rmse = error.rel_rmse;
  m.max_abs = error.max_abs;
  return m;
}

std::vector<Measurement> run_bench(const BenchOptions& o, const std::vector<Scene>& scenes,
                                   const std::vector<Size>& sizes, const std::vector<Variant>& variants) {
  const std::filesystem::path cache = o.cache.empty() ? reference::default_cache_dir() : std::filesystem::path(o.cache);
  std::vector<Measurement> rows;
  for (const auto& scene : scenes)
    for (const auto& size : sizes) {
      const Image expected = reference::cached_reference(scene, size.width, size.height, cache).airlight;
      double floor_ns = 0.0;
      if (o.floor) {
        const FloorTimes f = time_floor(size.width, size.height, o.warmup, o.frames);
        std::fprintf(report_stream(o.csv),
                     "floor %dx%d: full-screen pass %s s, march of %d steps %s s, %s ns per sample\n", size.width,
                     size.height, number(f.fullscreen_s).c_str(), floor_steps, number(f.march_s).c_str(),
                     number(f.ns_per_sample).c_str());
        floor_ns = f.ns_per_sample;
      }
      for (const auto& variant : variants) {
        rows.push_back(measure(variant, scene, size, expected, o));
        rows.back().floor_ns = floor_ns;
      }
    }
  return rows;
}

// ---- output ---------------------------------------------------------------------


void write_csv(const std::string& file, const std::vector<std::vector<std::string>>& rows) {
  std::ostringstream out;
  for (const auto& row : rows) {
    for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << csv_field(row[i]);
    out << "\n";
  }
  write_csv_output(file, out.str());
}

// Pass names in the order first seen, so the columns follow the frame's passes.
std::vector<std::string> pass_names(const std::vector<Measurement>& rows) {
  std::vector<std::string> names;
  for (const auto& m : rows)
    for (const auto& [pass, s] : m.pass_median_s)
      if (std::find(names.begin(), names.end(), pass) == names.end()) names.push_back(pass);
  return names;
}

void write_measurements(const std::string& file, const std::vector<Measurement>& rows) {
  const auto passes = pass_names(rows);
  std::vector<std::string> header{"scene", "width", "height", "method", "settings", "frames",
                                  "frame_median_s", "frame_min_s", "frame_max_s", "first_frame_s"};
  for (const auto& pass : passes) header.push_back(pass + "_median_s");
  header.insert(header.end(),
                {"gpu_mib", "peak_rss_mib", "rel_rmse", "max_abs", "ns_per_sample", "floor_ratio", "stats"});
  std::vector<std::vector<std::string>> table{header};
  for (const auto& m : rows) {
    std::vector<std::string> row{m.scene, std::to_string(m.size.width), std::to_string(m.size.height), m.method,
                                 m.settings, std::to_string(m.frames), number(m.frame.median),
                                 number(m.frame.min), number(m.frame.max), number(m.first_frame_s)};
    for (const auto& pass : passes) {
      const auto it = std::find_if(m.pass_median_s.begin(), m.pass_median_s.end(),
                                   [&](const auto& p) { return p.first == pass; });
      row.push_back(it == m.pass_median_s.end() ? "" : number(it->second));
    }
    row.insert(row.end(), {number(m.gpu_mib), number(m.peak_rss_mib), number(m.rel_rmse), number(m.max_abs)});
    const double ns = m.samples > 0.0 ? m.method_s / m.samples * 1e9 : 0.0;
    row.push_back(ns > 0.0 ? number(ns) : "");
    row.push_back(ns > 0.0 && m.floor_ns > 0.0 ? number(ns / m.floor_ns) : "");
    std::string stats;
    for (const auto& [name, value] : m.stats) stats += (stats.empty() ? "" : " ") + name + "=" + number(value);
    row.push_back(stats);
    table.push_back(std::move(row));
  }
  write_csv(file, table);
}

bool same_case(const Measurement& a, const Measurement& b) {
  return a.scene == b.scene && a.size.width == b.size.width && a.size.height == b.size.height;
}

// The rows of each (scene, size), in run order.
std::vector<std::vector<const Measurement*>> cases(const std::vector<Measurement>& rows) {
  std::vector<std::vector<const Measurement*>> groups;
  for (const auto& m : rows) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return same_case(*g.front(), m); });
    if (it == groups.end()) groups.push_back({&m});
    else it->push_back(&m);
  }
  return groups;
}

std::string case_label(const Measurement& m, const std::string& separator) {
  return m.scene + separator + std::to_string(m.size.width) + "x" + std::to_string(m.size.height);
}

// FILE.png for one (scene, size); FILE-<scene>-<WxH>.png for each of several.
// A line per method and choice of its outer sweeps' values, its last sweep along the line.
void write_plots(const std::filesystem::path& file, const std::vector<Measurement>& rows) {
  const auto groups = cases(rows);
  for (const auto& group : groups) {
    std::vector<PlotSeries> series;
    for (const auto* m : group) {
      if (series.empty() || series.back().label != m->series) series.push_back({m->series, {}});
      series.back().points.push_back({m->frame.median, m->rel_rmse});
    }
    std::filesystem::path out = file;
    if (groups.size() > 1)
      out.replace_filename(file.stem().string() + "-" + case_label(*group.front(), "-") + file.extension().string());
    write_plot(case_label(*group.front(), ", "), series, out);
  }
}

// The cheapest run (median frame time) of `method` in the group with rRMSE ≤ E,
// or of the brute-force baseline when `method` is empty.
const Measurement* cheapest(const std::vector<const Measurement*>& group, const std::string& method, double e,
                            bool baseline_only = false) {
  const Measurement* best = nullptr;
  for (const auto* m : group) {
    const bool wanted = baseline_only ? m->baseline : m->method == method;
    if (wanted && m->rel_rmse <= e && (!best || m->frame.median < best->frame.median)) best = m;
  }
  return best;
}

// One row per (scene, size) and method: its cheapest run reaching rRMSE ≤ E and
// that run's time over the baseline's, or a note saying which is missing.
std::vector<std::vector<std::string>> equal_quality_table(const std::vector<Measurement>& rows, double e,
                                                          const std::vector<std::string>& methods) {
  std::vector<std::vector<std::string>> table{{"scene", "width", "height", "method", "settings", "frame_median_s",
                                               "rel_rmse", "time_ratio", "time_ratio_best", "note"}};
  for (const auto& group : cases(rows)) {
    const Measurement& c = *group.front();
    const Measurement* baseline = cheapest(group, "", e, true);
    const Measurement* best = cheapest(group, "raymarch", e);  // any raymarch settings: the best run
    for (const auto& method : methods) {
      std::vector<std::string> row{c.scene, std::to_string(c.size.width), std::to_string(c.size.height), method};
      const Measurement* m = cheapest(group, method, e);
      if (!m) {
        row.insert(row.end(), {"", "", "", "", "", "no run reaches rRMSE <= " + number(e)});
      } else {
        row.insert(row.end(), {m->settings, number(m->frame.median), number(m->rel_rmse)});
        row.push_back(baseline ? number(m->frame.median / baseline->frame.median) : "");
        row.push_back(best ? number(m->frame.median / best->frame.median) : "");
        row.push_back(baseline ? "" : "no baseline: no raymarch run with sampling=uniform jitter=none reaches rRMSE <= " + number(e));
      }
      table.push_back(std::move(row));
    }
  }
  return table;
}

// Columns padded to their widest cell.
void print_table(const std::vector<std::vector<std::string>>& table) {
  std::vector<size_t> widths(table.front().size(), 0);
  for (const auto& row : table)
    for (size_t i = 0; i < row.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
  for (const auto& row : table) {
    std::string line;
    for (size_t i = 0; i < row.size(); ++i) line += row[i] + std::string(widths[i] - row[i].size() + 2, ' ');
    std::printf("%s\n", line.substr(0, line.find_last_not_of(' ') + 1).c_str());
  }
}

std::filesystem::path equal_quality_file(const std::filesystem::path& csv) {
  std::filesystem::path file = csv;
  return file.replace_filename(csv.stem().string() + "-equal-quality" + csv.extension().string());
}

void check_outputs(const BenchOptions& o, const std::vector<Size>& sizes, const std::vector<Variant>& variants) {
  check_csv_output("--csv", o.csv);
  if (is_standard_output(o.csv) && o.equal_quality > 0.0)
    throw InputError("--equal-quality", "--csv -",
                     "its table is written beside the CSV file, as FILE-equal-quality.csv, and standard output is no "
                     "file: give --csv FILE");
  if (!o.plot.empty()) check_output_file("--plot", o.plot, {".png"});
  check_output_dir("--cache", o.cache.empty() ? reference::default_cache_dir() : std::filesystem::path(o.cache));
  std::vector<const MethodInfo*> methods{&find_method("reference")};
  for (const auto& v : variants) methods.push_back(v.method);
  // The reference's two images stay cached beside each run.
  for (const Size& size : sizes) check_memory("--sizes", size, methods, 2);
}

// Every run on every scene and size, the reference's two images kept beside it.
void check_frame_memory(const std::vector<Scene>& scenes, const std::vector<Size>& sizes,
                        const std::vector<Variant>& variants) {
  std::vector<MethodRun> runs;
  for (const auto& v : variants) runs.push_back({v.method, &v.settings});
  for (const Scene& scene : scenes)
    for (const Size& size : sizes) app::check_frame_memory(scene, "--sizes", size, runs, 2, true);
}

void bench(const BenchOptions& o) {
  const std::vector<Variant> variants = plan_variants(o.methods, o.sweeps, o.assignments);
  std::vector<Size> sizes;
  for (const auto& text : o.sizes) sizes.push_back(parse_size(text, "--sizes"));
  check_outputs(o, sizes, variants);
  const std::vector<Scene> scenes = load_scenes(o);
  check_frame_memory(scenes, sizes, variants);
  const std::vector<Measurement> rows = run_bench(o, scenes, sizes, variants);
  OutputBatch outputs;
  write_measurements(o.csv, rows);
  if (!o.plot.empty()) write_plots(o.plot, rows);
  if (o.equal_quality > 0.0) {
    const auto table = equal_quality_table(rows, o.equal_quality, o.methods);
    std::printf("equal quality: the cheapest run with rRMSE <= %s; time_ratio: its median frame time over the "
                "cheapest raymarch run with jitter=none that reaches it (brute force); time_ratio_best: over the "
                "cheapest raymarch run of any settings that reaches it\n",
                number(o.equal_quality).c_str());
    print_table(table);
    write_csv(equal_quality_file(o.csv), table);
  }
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
