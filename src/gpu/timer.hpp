#pragma once
// Time per pass (docs/design.md §3: every method reports its GPU time per pass). On a
// GPU: a pair of GL_TIMESTAMP queries, which, unlike GL_TIME_ELAPSED, may run
// inside another timer's pass (the light volume mesh times its build inside
// its method's). On llvmpipe the queries do not see compute dispatches (and
// report garbage for draws), but there the CPU is the GPU: each pass is
// bracketed by glFinish and timed by the wall clock instead. One timer's
// passes do not nest; results are read once, after the frame.
#include "gpu/gl.hpp"

#include <airlight/timing.hpp>

#include <chrono>
#include <string>
#include <vector>

namespace airlight::gpu {

class PassTimer {
public:
  PassTimer();
  void begin(const std::string& pass);
  void end();
  // Waits for the queries and returns seconds per pass, in the order begun.
  std::vector<PassTime> results();

private:
  struct Pending {
    std::string pass;
    Query began, ended;                          // GPU clock: timestamps
    std::chrono::steady_clock::time_point start; // software renderer: wall clock
    double seconds = 0.0;
  };
  bool wall_clock_;
  std::vector<Pending> pending_;
};

// Times one pass for the lifetime of the scope.
class ScopedPass {
public:
  ScopedPass(PassTimer& timer, const std::string& pass) : timer_(timer) { timer_.begin(pass); }
  ~ScopedPass() { timer_.end(); }
  ScopedPass(const ScopedPass&) = delete;
  ScopedPass& operator=(const ScopedPass&) = delete;

private:
  PassTimer& timer_;
};

}  // namespace airlight::gpu
