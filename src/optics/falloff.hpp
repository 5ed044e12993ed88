#pragma once
// Panel breaks for the 1/max(r, ε)² falloff along a line passing at distance r0
// from a point light whose foot (point of closest approach) is at parameter tc.
#include <algorithm>
#include <cmath>
#include <vector>

#include "optics/light.hpp"

namespace airlight::optics {

// The integrand varies on the scale of r itself, so breaks grade geometrically
// (×4) away from tc, starting at max(r0, ε); the kinks of the clamp at r = ε are
// breaks too. Covers at least `span` on either side; callers drop breaks outside.
inline std::vector<double> falloff_breaks(double tc, double r0, double span) {
  const double eps = min_light_distance;
  std::vector<double> breaks{tc};
  if (r0 < eps) {
    const double h = std::sqrt(eps * eps - r0 * r0);
    breaks.insert(breaks.end(), {tc - h, tc + h});
  }
  for (double step = std::max(r0, eps); step < 2.0 * span; step *= 4.0)
    breaks.insert(breaks.end(), {tc - step, tc + step});
  return breaks;
}

}  // namespace airlight::optics
