#include "app/bench_measurement.hpp"

#include <algorithm>

namespace airlight::app {

namespace {

bool same_case(const Measurement& a, const Measurement& b) {
  return a.scene == b.scene && a.size.width == b.size.width && a.size.height == b.size.height;
}

}  // namespace

std::vector<std::vector<const Measurement*>> cases(const std::vector<Measurement>& rows) {
  std::vector<std::vector<const Measurement*>> groups;
  for (const auto& m : rows) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return same_case(*g.front(), m); });
    if (it == groups.end()) groups.push_back({&m});
    else it->push_back(&m);
  }
  return groups;
}

std::string case_label(const Measurement& m, const std::string& separator) {
  return m.scene + separator + std::to_string(m.size.width) + "x" + std::to_string(m.size.height);
}

}  // namespace airlight::app
