#pragma once
// Time per pass (docs/design.md §3: every method reports its GPU time per pass). On a
// GPU: a pair of GL_TIMESTAMP queries, which, unlike GL_TIME_ELAPSED, may run
// inside another timer's pass (the light volume mesh times its build inside
// its method's). A frame never waits for them: its passes' queries are kept,
// with a few frames' before them, until the GPU has written them (ready()),
// and only a caller that waits for the GPU anyway (a read-back) waits for the
// last frame's (wait()). On llvmpipe the queries do not see compute dispatches
// (and report garbage for draws), but there the CPU is the GPU: each pass is
// bracketed by glFinish and timed by the wall clock instead. That is no wait
// on a query: glFinish waits for the pass's own work, which llvmpipe's threads
// run while this one waits, so the frame ends when its work does either way;
// what it costs is the overlap of one pass with the next.
// One timer's passes do not nest.
#include "gpu/gl.hpp"

#include <airlight/timing.hpp>

#include <chrono>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace airlight::gpu {

// A frame's passes and their seconds, in the order begun; `frame` counts the
// timer's end_frame() calls from 0 (-1: no frame).
struct FrameTimes {
  std::int64_t frame = -1;
  std::vector<PassTime> times;
};

class PassTimer {
public:
  PassTimer();
  void begin(const std::string& pass);
  void end();
  // The passes begun since the last end_frame() are a frame, read later.
  void end_frame();
  // The newest ended frame whose times the GPU has written, never waiting
  // (frame -1 before any). Frames older than it are dropped.
  FrameTimes ready() const;
  // The last ended frame's times, waiting for the GPU to write them.
  FrameTimes wait() const;
  // One measurement: end_frame(), then wait()'s times.
  std::vector<PassTime> results();

private:
  struct Pending {
    std::string pass;
    Query began, ended;                          // GPU clock: timestamps
    std::chrono::steady_clock::time_point start; // software renderer: wall clock
    double seconds = 0.0;
  };
  struct Frame {
    std::int64_t index = 0;
    std::vector<Pending> passes;
  };
  // Reads `frame`'s times from its queries: true when all were written (or waited for).
  bool read(Frame& frame, bool wait) const;
  FrameTimes take(size_t newest) const;

  bool wall_clock_;
  std::vector<Pending> open_;         // the frame being timed
  mutable std::deque<Frame> ended_;   // ended frames not yet read, oldest first
  mutable FrameTimes last_read_;
  std::int64_t frames_ = 0;
};

// Tests: time by timestamp queries on llvmpipe too, to follow a GPU's path
// (the times are garbage there; when they are read is what is tested). Read
// when a PassTimer is made.
void force_timestamp_queries(bool on);

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
