#pragma once
// bench's plan: its options, and the runs, sizes and scenes they name, checked
// before anything renders — the outputs writable, every run within its
// method's limits and the memory on every scene and size.
#include "app/method_settings.hpp"
#include "app/scene_source.hpp"

#include <airlight/scene.hpp>
#include <string>
#include <vector>

namespace airlight::app {

struct BenchOptions {
  std::vector<std::string> scene_files, builtins, methods, sweeps, assignments, sizes{"256x192"};
  std::string csv, plot, cache;
  int warmup = 1, frames = 5;
  double equal_quality = 0.0;  // 0: no equal-quality report
  bool floor = false;          // time the floor (floor.hpp) at each size
};

struct BenchPlan {
  std::vector<Variant> variants;  // in run order, per scene and size
  std::vector<Size> sizes;
  std::vector<Scene> scenes;
};

// Throws InputError naming the option at the first thing refused.
BenchPlan plan_bench(const BenchOptions& o);

}  // namespace airlight::app
