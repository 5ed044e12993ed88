#include "app/bench_equal_quality.hpp"
#include "app/bench_csv.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace airlight::app {

namespace {

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
        row.insert(row.end(), {"", "", "", "", "", "no run reaches rRMSE <= " + csv_number(e)});
      } else {
        row.insert(row.end(), {m->settings, csv_number(m->frame.median), csv_number(m->rel_rmse)});
        row.push_back(baseline ? csv_number(m->frame.median / baseline->frame.median) : "");
        row.push_back(best ? csv_number(m->frame.median / best->frame.median) : "");
        row.push_back(baseline ? "" : "no baseline: no raymarch run with sampling=uniform jitter=none reaches rRMSE <= " + csv_number(e));
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

}  // namespace

void write_equal_quality(const std::vector<Measurement>& rows, double e, const std::vector<std::string>& methods,
                         const std::string& csv) {
  const auto table = equal_quality_table(rows, e, methods);
  std::printf("equal quality: the cheapest run with rRMSE <= %s; time_ratio: its median frame time over the "
              "cheapest raymarch run with jitter=none that reaches it (brute force); time_ratio_best: over the "
              "cheapest raymarch run of any settings that reaches it\n",
              csv_number(e).c_str());
  print_table(table);
  write_csv_table(equal_quality_file(csv), table);
}

}  // namespace airlight::app
