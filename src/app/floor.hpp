#pragma once
// The floor of `airlight bench --floor` (floor.comp.glsl): a minimal
// full-screen pass and a minimal march, timed in the bench's own run, so that
// a method's cost per sample can be read against what this machine needs at
// least (docs/design.md §5).
#include "app/measure.hpp"

namespace airlight::app {

inline constexpr int floor_steps = 64;  // the minimal march's samples per pixel

struct FloorTimes {
  double fullscreen_s = 0.0;  // medians over the timed frames
  double march_s = 0.0;
  double ns_per_sample = 0.0;  // march_s over width × height × floor_steps
};

FloorTimes time_floor(int width, int height, int warmup, int frames);

}  // namespace airlight::app
