#pragma once
// bench's timing of one run: warm-up frames, then timed frames, each frame's
// time and its passes' times, and the GPU memory the first frame took.
#include "app/bench_measurement.hpp"

#include <airlight/method.hpp>
#include <string>
#include <vector>

namespace airlight::app {

// The shared frame's passes; every other pass is the method's own.
bool frame_pass(const std::string& pass);

// The timed frames' passes into `m`: each pass's median over the frames (a
// pass run several times in a frame counts once, summed) and own_median_s,
// the median of the frames' own-pass sums (not the sum of the passes' medians).
void summarize_passes(const std::vector<std::vector<PassTime>>& frames, Measurement* m);

// Renders W warm-up frames and F timed ones into `m` (times, GPU memory of the
// first frame over `gpu_before`); returns the last frame.
FrameImages time_frames(Method& method, const Scene& scene, Size size, int warmup, int frames, double gpu_before, Measurement* m);

}  // namespace airlight::app
