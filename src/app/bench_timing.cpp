#include "app/bench_timing.hpp"
#include "app/measure.hpp"
#include "core/progress.hpp"
#include "gpu/gl.hpp"

#include <algorithm>
#include <chrono>

namespace airlight::app {

namespace {

Spread spread(const std::vector<double>& values) {
  return {median(values), *std::min_element(values.begin(), values.end()),
          *std::max_element(values.begin(), values.end())};
}

// The value under `name` in a list kept in first-seen order, appended when absent.
template <typename T>
T& entry(std::vector<std::pair<std::string, T>>& list, const std::string& name) {
  const auto it = std::find_if(list.begin(), list.end(), [&](const auto& p) { return p.first == name; });
  return it != list.end() ? it->second : list.emplace_back(name, T{}).second;
}

}  // namespace

bool frame_pass(const std::string& pass) {
  return pass == "gbuffer" || pass == "depth" || pass == "shadow" || pass == "surface" || pass == "engine" ||
         pass == "readback";
}

void summarize_passes(const std::vector<std::vector<PassTime>>& frames, Measurement* m) {
  std::vector<std::pair<std::string, std::vector<double>>> pass_s;
  std::vector<double> own_s;
  for (const auto& times : frames) {
    std::vector<std::pair<std::string, double>> frame;
    for (const auto& t : times) entry(frame, t.pass) += t.seconds;
    for (const auto& [pass, seconds] : frame) entry(pass_s, pass).push_back(seconds);
    double own = 0.0;
    bool has_own = false;
    for (const auto& t : times)
      if (!frame_pass(t.pass)) {
        own += t.seconds;
        has_own = true;
      }
    if (has_own) own_s.push_back(own);
  }
  for (const auto& [pass, s] : pass_s) m->pass_median_s.emplace_back(pass, median(s));
  if (!own_s.empty()) m->own_median_s = median(own_s);
}

FrameImages time_frames(Method& method, const Scene& scene, Size size, int warmup, int frames, double gpu_before, Measurement* m) {
  Progress progress(m->scene + " " + std::to_string(size.width) + "x" + std::to_string(size.height) + " " +
                        m->method + " " + m->settings,
                    warmup + frames);
  std::vector<double> frame_s;
  std::vector<std::vector<PassTime>> pass_times;
  FrameImages frame;
  for (int i = 0; i < warmup + frames; ++i) {
    const auto start = std::chrono::steady_clock::now();
    frame = render(method, scene, size.width, size.height, false);  // bench measures L_air alone
    const double seconds = seconds_since(start);
    if (i == 0) {
      m->gpu_mib = (static_cast<double>(gpu::allocated_bytes()) - gpu_before) / (1 << 20);
      m->first_frame_s = seconds;
    }
    progress.advance();
    if (i < warmup) continue;
    frame_s.push_back(seconds);
    pass_times.push_back(frame.times);
    if (frame.readback_s > 0.0) pass_times.back().push_back({"readback", frame.readback_s});  // part of the frame's time
  }
  m->frame = spread(frame_s);
  summarize_passes(pass_times, m);
  return frame;
}

}  // namespace airlight::app
