#pragma once
// Every read of a query's result goes through here, so that a frame never waits
// for its own queries (docs/design.md §2, gpu/): a poll that never waits, and a
// wait, counted, which only a caller that asked for the GPU's results (a
// read-back, a one-shot measurement) makes.
#include "gpu/gl.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace airlight::gpu {

// The query's result if the GPU has written it; never waits.
std::optional<GLuint64> poll_query(const Query& query);
// The query's result, waiting for the GPU to write it.
GLuint64 wait_query(const Query& query);
// The wait_query calls this process has made: a test's count of stalls.
std::int64_t blocking_query_reads();

// Fragment shader invocations counted around a frame's draws
// (GL_ARB_pipeline_statistics_query), frame after frame, each count read once
// the GPU has it: a small ring of queries in flight.
class InvocationCounter {
public:
  void prepare();  // needs a current context; without the extension it counts nothing
  void begin();
  void end();
  // The newest count the GPU has written, never waiting; nullopt before the
  // first or without the extension. Once the GPU is idle (after a read-back),
  // the last frame's.
  std::optional<double> latest() const;

private:
  bool available_ = false;
  mutable std::vector<Query> in_flight_;  // oldest first; the last begun at the back
  mutable std::vector<Query> spare_;
  mutable std::optional<double> latest_;
};

}  // namespace airlight::gpu
