#pragma once
// The time one pass of a frame took (docs/design.md §3: every method reports
// its GPU time per pass).
#include <airlight/export.hpp>
#include <string>

namespace airlight {

struct AIRLIGHT_API PassTime {
  std::string pass;
  double seconds = 0.0;
};

}  // namespace airlight
