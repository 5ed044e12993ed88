// `airlight compare` (docs/design.md §5, issue 6): the reference and each named method
// on one scene at one size, as a contact sheet and a CSV of their errors.
#include "app/commands.hpp"
#include "app/csv.hpp"
#include "app/contact_sheet.hpp"
#include "app/measure.hpp"
#include "app/method_settings.hpp"
#include "app/output_check.hpp"
#include "reference/cache.hpp"
#include "app/scene_source.hpp"
#include "app/tone_options.hpp"
#include "core/atomic_file.hpp"
#include "core/image_io.hpp"
#include "core/metrics.hpp"
#include "core/progress.hpp"

#include <airlight/error.hpp>
#include <airlight/method.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

namespace airlight::app {

namespace {

namespace fs = std::filesystem;

struct CompareOptions {
  SceneSource scene;
  std::string methods, size = "256x192", pass = "airlight", out, csv, images, cache;
  std::vector<std::string> assignments;
  ToneOptions tone;
};

// One image with its costs and its error against the reference.
struct Result {
  std::string method, settings, changed, note;  // changed: the settings that differ from the defaults
  Image image;
  double prepare_s = 0.0, render_s = 0.0, mean = 0.0;
  bool cached = false;
  ImageError error;
};

// The mean over pixels and channels; a non-finite value is a method's bug.
double mean_radiance(const Image& image, const std::string& method) {
  double sum = 0.0;
  for (const auto& p : image.pixels)
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(p[c])) throw Failure("method '" + method + "' produced non-finite values");
      sum += p[c];
    }
  return sum / (3.0 * static_cast<double>(image.pixels.size()));
}

// The settings of `settings` that differ from its method's defaults: what the
// sheet's labels show, as the full list would not fit under a small image.
std::string changed_settings(const MethodInfo& info, const Settings& settings) {
  const std::vector<std::string> defaults = split(Settings(info.settings).describe(), ' ');
  std::string changed;
  for (const auto& s : split(settings.describe(), ' '))
    if (std::find(defaults.begin(), defaults.end(), s) == defaults.end()) changed += (changed.empty() ? "" : " ") + s;
  return changed.empty() ? "(defaults)" : changed;
}

Result reference_result(const Scene& scene, Size size, Pass pass, const fs::path& cache_dir) {
  const std::string key = reference::reference_key(scene, size.width, size.height);
  reference::CachedReference frame = reference::cached_reference(scene, size.width, size.height, cache_dir);
  std::fprintf(stderr, "compare: reference %s %s (key %s)\n",
               frame.cached ? "read from the cache" : "rendered into the cache", cache_dir.c_str(), key.c_str());
  Result r;
  r.method = "reference";
  r.settings = Settings(find_method("reference").settings).describe();  // the defaults the cache renders with
  r.changed = "(defaults)";
  r.note = frame.cached ? "cached" : "";
  r.render_s = frame.seconds;
  r.cached = frame.cached;
  r.image = select_pass(FrameImages{std::move(frame.airlight), std::move(frame.surface), {}, 0.0, {}}, pass);
  return r;
}

Result method_result(const MethodEntry& entry, const Scene& scene, Size size, Pass pass) {
  Result r;
  r.method = entry.info->name;
  r.settings = entry.settings.describe();
  r.changed = changed_settings(*entry.info, entry.settings);
  with_memory_hint(scene, size, {entry.info, &entry.settings}, [&] {
    auto method = entry.info->create(entry.settings);
    auto start = std::chrono::steady_clock::now();
    method->prepare(scene);
    r.prepare_s = seconds_since(start);
    start = std::chrono::steady_clock::now();
    r.image = select_pass(render(*method, scene, size.width, size.height, pass != Pass::airlight), pass);
    r.render_s = seconds_since(start);
  });
  return r;
}

void measure(Result& r, const Image& reference, float exposure) {
  r.mean = mean_radiance(r.image, r.method);
  r.error = compare_images(r.image, reference, exposure);
}

// The columns README.md "## Comparing" documents.
void write_csv(const std::vector<Result>& results, const std::string& pass, const std::string& file) {
  std::ostringstream out;
  out << "method,settings,width,height,pass,rel_rmse,max_abs,psnr_db,mean_radiance,reference_mean,prepare_s,render_s,"
         "cached\n";
  char numbers[512];
  for (const auto& r : results) {
    std::snprintf(numbers, sizeof numbers, "%d,%d,%s,%.9g,%.9g,%.9g,%.9g,%.9g,%.6f,%.6f,%d", r.image.width,
                  r.image.height, pass.c_str(), r.error.rel_rmse, r.error.max_abs, r.error.psnr_db, r.mean,
                  r.error.mean_reference, r.prepare_s, r.render_s, r.cached ? 1 : 0);
    out << csv_field(r.method) << ',' << csv_field(r.settings) << ',' << numbers << '\n';
  }
  write_csv_output(file, out.str());
}

// reference.pfm, then <index>_<method>.pfm in the order of --methods.
void write_images(const std::vector<Result>& results, const fs::path& dir, OutputBatch& outputs) {
  outputs.create_directories(dir);
  write_image(results[0].image, dir / "reference.pfm");
  for (size_t i = 1; i < results.size(); ++i)
    write_image(results[i].image, dir / (std::to_string(i) + "_" + results[i].method + ".pfm"));
}

// The heat maps' scale goes to stderr too, for whoever reads the run's log.
void write_sheet(const std::vector<Result>& results, const ToneMap& tone, const fs::path& file) {
  std::vector<SheetEntry> entries;
  for (const auto& r : results)
    entries.push_back({r.method, r.changed, r.note, r.prepare_s + r.render_s, r.error.rel_rmse, &r.image});
  const HeatScale scale = heat_scale(entries);
  std::fprintf(stderr, "compare: error maps' %s\n", describe(scale).c_str());
  write_contact_sheet(entries, scale, tone, file);
}

void check_outputs(const CompareOptions& o, Size size, const std::vector<MethodEntry>& entries) {
  check_output_file("--out", o.out, {".png"});
  if (!o.csv.empty()) check_csv_output("--csv", o.csv);
  if (!o.images.empty()) check_output_dir("--images", o.images);
  check_output_dir("--cache", o.cache.empty() ? reference::default_cache_dir() : fs::path(o.cache));
  std::vector<const MethodInfo*> methods{&find_method("reference")};
  for (const auto& e : entries) methods.push_back(e.info);
  // Every result's image is kept for the sheet, and the reference's surface with it.
  check_memory("--size", size, methods, static_cast<int>(entries.size()) + 2);
}

// The reference at its defaults (what the cache renders with), then the entries.
std::vector<MethodRun> runs(const std::vector<MethodEntry>& entries) {
  static const Settings reference_defaults(find_method("reference").settings);
  std::vector<MethodRun> all{{&find_method("reference"), &reference_defaults}};
  for (const auto& e : entries) all.push_back({e.info, &e.settings});
  return all;
}

void compare(const CompareOptions& o) {
  // Every argument is checked before the first (slow) render.
  const Size size = parse_size(o.size, "--size");
  const std::vector<MethodEntry> entries = parse_entries(o.methods, o.assignments);
  check_outputs(o, size, entries);
  const Pass pass = o.pass == "composite" ? Pass::composite : Pass::airlight;
  const Scene scene = o.scene.load();
  check_frame_memory(scene, "--size", size, runs(entries), static_cast<int>(entries.size()) + 2, true);
  std::vector<Result> results{
      reference_result(scene, size, pass, o.cache.empty() ? reference::default_cache_dir() : fs::path(o.cache))};
  {
    Progress progress("compare", static_cast<long>(entries.size()));
    for (const auto& entry : entries) {
      results.push_back(method_result(entry, scene, size, pass));
      progress.advance();
    }
  }
  const ToneMap tone = o.tone.resolve(results[0].image, "compare");  // auto: measured on the reference
  for (auto& r : results) measure(r, results[0].image, tone.exposure);
  OutputBatch outputs;
  if (!o.images.empty()) write_images(results, o.images, outputs);
  if (!o.csv.empty()) write_csv(results, o.pass, o.csv);
  write_sheet(results, tone, o.out);
  outputs.commit();
}

}  // namespace

Run add_compare_command(CLI::App& cli) {
  auto o = std::make_shared<CompareOptions>();
  auto* command = cli.add_subcommand("compare", "render the reference and several methods; write a contact sheet");
  o->scene.add_options(*command);
  command
      ->add_option("--methods", o->methods,
                   "methods in order, separated by ','; an entry may carry its own settings: "
                   "NAME:key=value;key=value (a method may appear several times)")
      ->required();
  command->add_option("--set", o->assignments, "method.key=value for every entry of that method (repeatable)");
  command->add_option("--size", o->size, "image size WxH")->capture_default_str();
  command->add_option("--out", o->out, "contact sheet PNG")->required();
  command->add_option("--csv", o->csv, "CSV of the errors and times (README: Comparing); -: standard output");
  command->add_option("--images", o->images, "directory for the images as PFM: reference.pfm, <index>_<method>.pfm");
  command->add_option("--pass", o->pass, "what to compare (docs/design.md §6 measures the airlight)")
      ->check(CLI::IsMember({"airlight", "composite"}))
      ->capture_default_str();
  o->tone.add_options(*command);
  command->add_option("--cache", o->cache, "reference cache directory (default $AIRLIGHT_CACHE, else ~/.cache/airlight)");
  return [o] { compare(*o); };
}

}  // namespace airlight::app
