#pragma once
// bench's measurement of one run (one CSV row), and the runs grouped by case:
// a scene at a size, where the plots and the equal-quality table compare them.
#include "app/scene_source.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace airlight::app {

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
  // The method's own time (README "Benchmarking"): the median over the timed
  // frames of each frame's sum of its own passes (all but the shared frame's:
  // frame_pass). None for a run without own passes (the CPU reference).
  std::optional<double> own_median_s;
  double gpu_mib = 0.0, peak_rss_mib = 0.0, rel_rmse = 0.0, max_abs = 0.0;
  bool baseline = false;  // raymarch, uniform steps without jitter: brute force, the equal-quality yardstick
  double samples = 0.0;   // light samples (marches) or fragments (planes) of a frame; 0: not a sampling method
  double floor_ns = 0.0;  // the floor's ns per sample at this size; 0: not timed
  double first_frame_s = 0.0;  // the first frame: it compiles the programs of a new define set
  std::vector<std::pair<std::string, double>> stats;  // the method's counters of the last frame
};

// The rows of each (scene, size), in run order.
std::vector<std::vector<const Measurement*>> cases(const std::vector<Measurement>& rows);

// "scene<separator>WxH".
std::string case_label(const Measurement& m, const std::string& separator);

}  // namespace airlight::app
