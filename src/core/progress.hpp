#pragma once
// Progress of long work on stderr, shown only when stderr is a terminal.
#include <atomic>
#include <chrono>
#include <string>

namespace airlight {

class Progress {
public:
  Progress(std::string label, long total);
  ~Progress();
  void advance(long n = 1);  // thread-safe

private:
  std::string label_;
  long total_;
  std::atomic<long> done_{0};
  std::atomic<int> last_percent_{-1};
  bool enabled_;
};

}  // namespace airlight
