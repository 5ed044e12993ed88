#include "app/bench_plots.hpp"
#include "app/plot.hpp"

namespace airlight::app {

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

}  // namespace airlight::app
