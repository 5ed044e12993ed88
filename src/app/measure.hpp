#pragma once
// Measurements shared by render's report and bench: wall-clock seconds and the
// process's peak resident memory.
#include <chrono>
#include <vector>

namespace airlight::app {

double seconds_since(std::chrono::steady_clock::time_point start);

// The middle value (the mean of the two middle ones for an even count); values must not be empty.
double median(std::vector<double> values);

// The process's peak resident set so far, in MiB (getrusage).
double peak_rss_mib();

}  // namespace airlight::app
