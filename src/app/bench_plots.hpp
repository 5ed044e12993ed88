#pragma once
// bench's plots (--plot FILE.png): rRMSE against the median frame time, log–log
// (plot.hpp), one per scene and size.
#include "app/bench_measurement.hpp"

#include <filesystem>
#include <vector>

namespace airlight::app {

// FILE.png for one (scene, size); FILE-<scene>-<WxH>.png for each of several.
// A line per method and choice of its outer sweeps' values, its last sweep along the line.
void write_plots(const std::filesystem::path& file, const std::vector<Measurement>& rows);

}  // namespace airlight::app
