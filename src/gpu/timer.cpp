#include "gpu/timer.hpp"

namespace airlight::gpu {

void PassTimer::begin(const std::string& pass) {
  pending_.push_back({pass, make_query(GL_TIME_ELAPSED)});
  glBeginQuery(GL_TIME_ELAPSED, pending_.back().query.id());
}

void PassTimer::end() { glEndQuery(GL_TIME_ELAPSED); }

std::vector<PassTime> PassTimer::results() {
  std::vector<PassTime> times;
  for (const auto& p : pending_) {
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(p.query.id(), GL_QUERY_RESULT, &nanoseconds);  // waits for the GPU
    times.push_back({p.pass, static_cast<double>(nanoseconds) * 1e-9});
  }
  pending_.clear();
  return times;
}

}  // namespace airlight::gpu
