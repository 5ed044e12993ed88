#pragma once
// bench's error-against-time plot: log–log, one colour per series (a method,
// or a method with its outer sweeps' values), each series' runs joined in sweep
// order, and the Pareto front over all of them.
#include <filesystem>
#include <string>
#include <vector>

namespace airlight::app {

struct PlotPoint {
  double seconds = 0.0;  // x: the frame's median time
  double error = 0.0;    // y: rRMSE against the reference
};

struct PlotSeries {
  std::string label;              // "raymarch", "raymarch sampling=equiangular"
  std::vector<PlotPoint> points;  // in sweep order
};

// The points not dominated by another (no other is at least as fast and at
// least as accurate, and better in one), sorted by time; error falls along it.
std::vector<PlotPoint> pareto_front(const std::vector<PlotPoint>& points);

// Writes a PNG. Points whose time or error is not positive and finite have no
// place on log axes and are left out (the reference against itself: error 0).
// Throws Failure when the file cannot be written.
void write_plot(const std::string& title, const std::vector<PlotSeries>& series, const std::filesystem::path& file);

}  // namespace airlight::app
