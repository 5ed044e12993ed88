#include "app/bench_plan.hpp"
#include "app/csv.hpp"
#include "app/output_check.hpp"
#include "reference/cache.hpp"

#include <airlight/error.hpp>
#include <airlight/method.hpp>

namespace airlight::app {

namespace {

std::vector<Scene> load_scenes(const BenchOptions& o) {
  if (o.scene_files.empty() && o.builtins.empty())
    throw InputError("--scene", "", "give --scene FILE or --builtin NAME (repeatable)");
  std::vector<Scene> scenes;
  for (const auto& file : o.scene_files) scenes.push_back(load_scene(file));
  for (const auto& name : o.builtins) scenes.push_back(builtin_scene(name, "--builtin"));
  return scenes;
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

}  // namespace

BenchPlan plan_bench(const BenchOptions& o) {
  BenchPlan plan;
  plan.variants = plan_variants(o.methods, o.sweeps, o.assignments);
  for (const auto& text : o.sizes) plan.sizes.push_back(parse_size(text, "--sizes"));
  check_outputs(o, plan.sizes, plan.variants);
  plan.scenes = load_scenes(o);
  check_frame_memory(plan.scenes, plan.sizes, plan.variants);
  return plan;
}

}  // namespace airlight::app
