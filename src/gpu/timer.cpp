#include "gpu/timer.hpp"

namespace airlight::gpu {

PassTimer::PassTimer() : wall_clock_(software_renderer()) {}

void PassTimer::begin(const std::string& pass) {
  if (wall_clock_) {
    glFinish();  // the pass starts when everything before it is done
    pending_.push_back({pass, Query(), Query(), std::chrono::steady_clock::now()});
    return;
  }
  pending_.push_back({pass, make_query(GL_TIMESTAMP), make_query(GL_TIMESTAMP), {}});
  glQueryCounter(pending_.back().began.id(), GL_TIMESTAMP);
}

void PassTimer::end() {
  if (!wall_clock_) return glQueryCounter(pending_.back().ended.id(), GL_TIMESTAMP);
  glFinish();
  Pending& p = pending_.back();
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - p.start).count();
}

std::vector<PassTime> PassTimer::results() {
  std::vector<PassTime> times;
  for (auto& p : pending_) {
    if (!wall_clock_) {
      GLuint64 start = 0, end = 0;
      glGetQueryObjectui64v(p.began.id(), GL_QUERY_RESULT, &start);  // waits for the GPU
      glGetQueryObjectui64v(p.ended.id(), GL_QUERY_RESULT, &end);
      p.seconds = static_cast<double>(end - start) * 1e-9;
    }
    times.push_back({p.pass, p.seconds});
  }
  pending_.clear();
  return times;
}

}  // namespace airlight::gpu
