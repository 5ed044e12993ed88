#include "gpu/timer.hpp"

namespace airlight::gpu {

PassTimer::PassTimer() : wall_clock_(software_renderer()) {}

void PassTimer::begin(const std::string& pass) {
  if (wall_clock_) {
    glFinish();  // the pass starts when everything before it is done
    pending_.push_back({pass, Query(), std::chrono::steady_clock::now()});
    return;
  }
  pending_.push_back({pass, make_query(GL_TIME_ELAPSED), {}});
  glBeginQuery(GL_TIME_ELAPSED, pending_.back().query.id());
}

void PassTimer::end() {
  if (!wall_clock_) return glEndQuery(GL_TIME_ELAPSED);
  glFinish();
  Pending& p = pending_.back();
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - p.start).count();
}

std::vector<PassTime> PassTimer::results() {
  std::vector<PassTime> times;
  for (auto& p : pending_) {
    if (!wall_clock_) {
      GLuint64 nanoseconds = 0;
      glGetQueryObjectui64v(p.query.id(), GL_QUERY_RESULT, &nanoseconds);  // waits for the GPU
      p.seconds = static_cast<double>(nanoseconds) * 1e-9;
    }
    times.push_back({p.pass, p.seconds});
  }
  pending_.clear();
  return times;
}

}  // namespace airlight::gpu
