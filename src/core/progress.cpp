#include "core/progress.hpp"

#include <cstdio>
#include <unistd.h>

namespace airlight {

Progress::Progress(std::string label, long total)
    : label_(std::move(label)), total_(total > 0 ? total : 1), enabled_(isatty(STDERR_FILENO) != 0) {}

Progress::~Progress() {
  if (enabled_ && last_percent_.load() >= 0) std::fprintf(stderr, "\r%s: done      \n", label_.c_str());
}

void Progress::advance(long n) {
  if (!enabled_) return;
  const long done = done_.fetch_add(n) + n;
  const int percent = static_cast<int>(100 * done / total_);
  int last = last_percent_.load();
  // Only the thread that moves the percentage on prints, so lines never interleave.
  while (percent > last) {
    if (last_percent_.compare_exchange_weak(last, percent)) {
      std::fprintf(stderr, "\r%s: %3d%%", label_.c_str(), percent);
      std::fflush(stderr);
      return;
    }
  }
}

}  // namespace airlight
