#include "app/bench_csv.hpp"
#include "app/csv.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace airlight::app {

namespace {

// Pass names in the order first seen, so the columns follow the frame's passes.
std::vector<std::string> pass_names(const std::vector<Measurement>& rows) {
  std::vector<std::string> names;
  for (const auto& m : rows)
    for (const auto& [pass, s] : m.pass_median_s)
      if (std::find(names.begin(), names.end(), pass) == names.end()) names.push_back(pass);
  return names;
}

}  // namespace

std::string csv_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

void write_csv_table(const std::string& file, const std::vector<std::vector<std::string>>& rows) {
  std::ostringstream out;
  for (const auto& row : rows) {
    for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << csv_field(row[i]);
    out << "\n";
  }
  write_csv_output(file, out.str());
}

void write_measurements(const std::string& file, const std::vector<Measurement>& rows) {
  const auto passes = pass_names(rows);
  std::vector<std::string> header{"scene", "width", "height", "method", "settings", "frames",
                                  "frame_median_s", "frame_min_s", "frame_max_s", "first_frame_s", "own_median_s"};
  for (const auto& pass : passes) header.push_back(pass + "_median_s");
  header.insert(header.end(),
                {"gpu_mib", "peak_rss_mib", "rel_rmse", "max_abs", "ns_per_sample", "floor_ratio", "stats"});
  std::vector<std::vector<std::string>> table{header};
  for (const auto& m : rows) {
    std::vector<std::string> row{m.scene, std::to_string(m.size.width), std::to_string(m.size.height), m.method,
                                 m.settings, std::to_string(m.frames), csv_number(m.frame.median),
                                 csv_number(m.frame.min), csv_number(m.frame.max), csv_number(m.first_frame_s),
                                 m.own_median_s ? csv_number(*m.own_median_s) : ""};
    for (const auto& pass : passes) {
      const auto it = std::find_if(m.pass_median_s.begin(), m.pass_median_s.end(),
                                   [&](const auto& p) { return p.first == pass; });
      row.push_back(it == m.pass_median_s.end() ? "" : csv_number(it->second));
    }
    row.insert(row.end(), {csv_number(m.gpu_mib), csv_number(m.peak_rss_mib), csv_number(m.rel_rmse), csv_number(m.max_abs)});
    const double ns = m.samples > 0.0 ? m.own_median_s.value_or(0.0) / m.samples * 1e9 : 0.0;
    row.push_back(ns > 0.0 ? csv_number(ns) : "");
    row.push_back(ns > 0.0 && m.floor_ns > 0.0 ? csv_number(ns / m.floor_ns) : "");
    std::string stats;
    for (const auto& [name, value] : m.stats) stats += (stats.empty() ? "" : " ") + name + "=" + csv_number(value);
    row.push_back(stats);
    table.push_back(std::move(row));
  }
  write_csv_table(file, table);
}

}  // namespace airlight::app
