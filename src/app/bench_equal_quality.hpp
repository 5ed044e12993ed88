#pragma once
// bench's equal-quality table (--equal-quality E): per scene, size and method,
// the cheapest run with rRMSE <= E and its time over brute force's (raymarch,
// uniform steps, no jitter) and over the best raymarch run's that reach E.
#include "app/bench_measurement.hpp"

#include <string>
#include <vector>

namespace airlight::app {

// Prints the table and writes it beside `csv` as FILE-equal-quality.csv.
void write_equal_quality(const std::vector<Measurement>& rows, double e, const std::vector<std::string>& methods,
                         const std::string& csv);

}  // namespace airlight::app
