#pragma once
// A number as messages show it: "0.05", "1e+39", "nan" — the scene loader's and the
// per-frame checks' alike, so a value refused in a file and in a frame reads the same.
#include <sstream>
#include <string>

namespace airlight {

inline std::string number_text(double x) {
  std::ostringstream out;
  out << x;
  return out.str();
}

}  // namespace airlight
