#include "gpu/timer.hpp"
#include "gpu/query.hpp"

#include <atomic>
#include <optional>

namespace airlight::gpu {

namespace {

std::atomic<bool> forced_timestamps{false};

// A GPU runs a frame or two behind; past this many ended frames the oldest is dropped unread.
constexpr size_t frames_in_flight = 4;

}  // namespace

void force_timestamp_queries(bool on) { forced_timestamps = on; }

PassTimer::PassTimer() : wall_clock_(software_renderer() && !forced_timestamps) {}

void PassTimer::begin(const std::string& pass) {
  if (wall_clock_) {
    glFinish();  // the pass starts when everything before it is done
    open_.push_back({pass, Query(), Query(), std::chrono::steady_clock::now()});
    return;
  }
  open_.push_back({pass, make_query(GL_TIMESTAMP), make_query(GL_TIMESTAMP), {}});
  glQueryCounter(open_.back().began.id(), GL_TIMESTAMP);
}

void PassTimer::end() {
  if (!wall_clock_) return glQueryCounter(open_.back().ended.id(), GL_TIMESTAMP);
  glFinish();
  Pending& p = open_.back();
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - p.start).count();
}

void PassTimer::end_frame() {
  if (ended_.size() == frames_in_flight) ended_.pop_front();
  ended_.push_back({frames_++, std::move(open_)});
  open_.clear();
}

bool PassTimer::read(Frame& frame, bool wait) const {
  if (wall_clock_) return true;  // timed as they ran
  const auto value = [wait](const Query& q) { return wait ? std::optional(wait_query(q)) : poll_query(q); };
  for (Pending& p : frame.passes) {
    const std::optional<GLuint64> start = value(p.began), end = value(p.ended);
    if (!start || !end) return false;
    p.seconds = static_cast<double>(*end - *start) * 1e-9;
  }
  return true;
}

FrameTimes PassTimer::take(size_t newest) const {
  last_read_ = {ended_[newest].index, {}};
  for (const Pending& p : ended_[newest].passes) last_read_.times.push_back({p.pass, p.seconds});
  ended_.erase(ended_.begin(), ended_.begin() + static_cast<std::ptrdiff_t>(newest) + 1);
  return last_read_;
}

FrameTimes PassTimer::ready() const {
  for (size_t i = ended_.size(); i-- > 0;)
    if (read(ended_[i], false)) return take(i);
  return last_read_;
}

FrameTimes PassTimer::wait() const {
  if (ended_.empty()) return last_read_;
  read(ended_.back(), true);
  return take(ended_.size() - 1);
}

std::vector<PassTime> PassTimer::results() {
  end_frame();
  return wait().times;
}

}  // namespace airlight::gpu
