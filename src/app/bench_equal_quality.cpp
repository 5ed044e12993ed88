#include "app/bench_equal_quality.hpp"
#include "app/bench_csv.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>

namespace airlight::app {

namespace {

// What a ranking compares: a run's median frame time, or its own time (none
// for a run without own passes, which that ranking leaves out).
using Time = std::optional<double> (*)(const Measurement&);
std::optional<double> frame_time(const Measurement& m) { return m.frame.median; }
std::optional<double> own_time(const Measurement& m) { return m.own_median_s; }

bool is_baseline(const Measurement& m) { return m.baseline; }

// The cheapest run by `time` among those `wanted` with rRMSE ≤ E.
const Measurement* cheapest(const std::vector<const Measurement*>& group, const std::function<bool(const Measurement&)>& wanted,
                            double e, Time time) {
  const Measurement* best = nullptr;
  for (const auto* m : group)
    if (wanted(*m) && m->rel_rmse <= e && time(*m) && (!best || *time(*m) < *time(*best))) best = m;
  return best;
}

// One ranking's columns for `method`: its cheapest run by `time` reaching E
// (settings, time, rRMSE) and that time over the brute-force baseline's and
// over the best raymarch run's, both the cheapest by the same `time`.
std::vector<std::string> ranked(const std::vector<const Measurement*>& group, const std::string& method, double e,
                                Time time) {
  const auto of = [](const std::string& name) { return [name](const Measurement& m) { return m.method == name; }; };
  const Measurement* m = cheapest(group, of(method), e, time);
  if (!m) return {"", "", "", "", ""};
  const Measurement* baseline = cheapest(group, is_baseline, e, time);
  const Measurement* best = cheapest(group, of("raymarch"), e, time);  // any raymarch settings: the best run
  const auto ratio = [&](const Measurement* over) { return over ? csv_number(*time(*m) / *time(*over)) : ""; };
  return {m->settings, csv_number(*time(*m)), csv_number(m->rel_rmse), ratio(baseline), ratio(best)};
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

std::vector<std::vector<std::string>> equal_quality_table(const std::vector<Measurement>& rows, double e,
                                                          const std::vector<std::string>& methods) {
  std::vector<std::vector<std::string>> table{{"scene", "width", "height", "method", "settings", "frame_median_s",
                                               "rel_rmse", "time_ratio", "time_ratio_best", "own_settings",
                                               "own_median_s", "own_rel_rmse", "own_ratio", "own_ratio_best", "note"}};
  for (const auto& group : cases(rows)) {
    const Measurement& c = *group.front();
    const bool baseline = cheapest(group, is_baseline, e, frame_time);
    for (const auto& method : methods) {
      std::vector<std::string> row{c.scene, std::to_string(c.size.width), std::to_string(c.size.height), method};
      const auto by_frame = ranked(group, method, e, frame_time), by_own = ranked(group, method, e, own_time);
      row.insert(row.end(), by_frame.begin(), by_frame.end());
      row.insert(row.end(), by_own.begin(), by_own.end());
      if (by_frame[1].empty()) row.push_back("no run reaches rRMSE <= " + csv_number(e));
      else if (!baseline)
        row.push_back("no baseline: no raymarch run with sampling=uniform jitter=none reaches rRMSE <= " + csv_number(e));
      else row.push_back("");
      table.push_back(std::move(row));
    }
  }
  return table;
}

void write_equal_quality(const std::vector<Measurement>& rows, double e, const std::vector<std::string>& methods,
                         const std::string& csv) {
  const auto table = equal_quality_table(rows, e, methods);
  std::printf("equal quality: the cheapest run with rRMSE <= %s, ranked twice. By frame time: settings, "
              "frame_median_s, rel_rmse; time_ratio: its median frame time over the cheapest raymarch run with "
              "jitter=none that reaches it (brute force); time_ratio_best: over the cheapest raymarch run of any "
              "settings that reaches it. By own time (the method's passes alone: no G-buffer, shadow maps or "
              "read-back), each chosen by own time: own_settings, own_median_s, own_rel_rmse, own_ratio, "
              "own_ratio_best\n",
              csv_number(e).c_str());
  print_table(table);
  write_csv_table(equal_quality_file(csv), table);
}

}  // namespace airlight::app
