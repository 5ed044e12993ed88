#pragma once
// GPU time per pass from GL_TIME_ELAPSED queries (DESIGN §3: every method reports
// its GPU time per pass). Passes do not nest; results are read once, after the frame.
#include "gpu/gl.hpp"

#include <airlight/method.hpp>

#include <string>
#include <vector>

namespace airlight::gpu {

class PassTimer {
public:
  void begin(const std::string& pass);
  void end();
  // Waits for the queries and returns seconds per pass, in the order begun.
  std::vector<PassTime> results();

private:
  struct Pending {
    std::string pass;
    Query query;
  };
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
