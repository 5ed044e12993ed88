#include "gpu/query.hpp"

#include <atomic>

namespace airlight::gpu {

namespace {

std::atomic<std::int64_t> waits{0};

// A GPU runs a frame or two behind; past this many counts in flight the oldest is dropped unread.
constexpr size_t counts_in_flight = 4;

}  // namespace

// One read that leaves `value` alone while the result is not there, rather
// than an availability check and a read: llvmpipe recomputes a pipeline
// statistics result at each fetch, scaling it again (docs/decisions.md "The
// method's own time and frames that never wait").
std::optional<GLuint64> poll_query(const Query& query) {
  constexpr GLuint64 unwritten = ~GLuint64{0};
  GLuint64 value = unwritten;
  glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT_NO_WAIT, &value);
  if (value == unwritten) return std::nullopt;
  return value;
}

GLuint64 wait_query(const Query& query) {
  ++waits;
  GLuint64 value = 0;
  glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &value);
  return value;
}

std::int64_t blocking_query_reads() { return waits.load(); }

void InvocationCounter::prepare() {
  available_ = epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query");
  in_flight_.clear();
  spare_.clear();
  latest_.reset();
}

void InvocationCounter::begin() {
  if (!available_) return;
  if (in_flight_.size() == counts_in_flight) {
    spare_.push_back(std::move(in_flight_.front()));
    in_flight_.erase(in_flight_.begin());
  }
  if (spare_.empty()) {
    GLuint id = 0;
    glGenQueries(1, &id);  // Mesa's glCreateQueries refuses the statistics targets
    spare_.emplace_back(id);
  }
  in_flight_.push_back(std::move(spare_.back()));
  spare_.pop_back();
  glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, in_flight_.back().id());
}

void InvocationCounter::end() {
  if (available_) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
}

std::optional<double> InvocationCounter::latest() const {
  for (size_t i = in_flight_.size(); i-- > 0;) {
    const std::optional<GLuint64> count = poll_query(in_flight_[i]);
    if (!count) continue;
    latest_ = static_cast<double>(*count);
    // This one and every older count are done with: the newest written wins.
    for (size_t j = 0; j <= i; ++j) spare_.push_back(std::move(in_flight_[j]));
    in_flight_.erase(in_flight_.begin(), in_flight_.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    break;
  }
  return latest_;
}

}  // namespace airlight::gpu
