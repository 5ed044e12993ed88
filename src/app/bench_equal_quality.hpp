#pragma once
// bench's equal-quality table (--equal-quality E): per scene, size and method,
// the cheapest run with rRMSE <= E and its time over brute force's (raymarch,
// uniform steps, no jitter) and over the best raymarch run's that reach E —
// ranked twice, by the whole frame's time and by the method's own time.
#include "app/bench_measurement.hpp"

#include <string>
#include <vector>

namespace airlight::app {

// The table, its header first: a row per scene, size and method, with the
// cheapest run by median frame time (settings, frame_median_s, rel_rmse,
// time_ratio, time_ratio_best) and, chosen on its own, the cheapest by own
// time (own_settings, own_median_s, own_rel_rmse, own_ratio, own_ratio_best):
// every ratio is over the baseline or raymarch run the same ranking picks.
std::vector<std::vector<std::string>> equal_quality_table(const std::vector<Measurement>& rows, double e,
                                                          const std::vector<std::string>& methods);

// Prints the table and writes it beside `csv` as FILE-equal-quality.csv.
void write_equal_quality(const std::vector<Measurement>& rows, double e, const std::vector<std::string>& methods,
                         const std::string& csv);

}  // namespace airlight::app
