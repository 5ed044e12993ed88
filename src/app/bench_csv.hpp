#pragma once
// bench's CSV files: numbers as bench writes them, tables, and the runs' table
// (README "Benchmarking" lists its columns).
#include "app/bench_measurement.hpp"

#include <string>
#include <vector>

namespace airlight::app {

// `value` with 6 significant digits (%.6g).
std::string csv_number(double value);

// `rows` as CSV into `file` ("-": standard output).
void write_csv_table(const std::string& file, const std::vector<std::vector<std::string>>& rows);

// One row per run, its passes' columns in the order the frames ran them.
void write_measurements(const std::string& file, const std::vector<Measurement>& rows);

}  // namespace airlight::app
