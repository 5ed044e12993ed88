#include "methods/kit/method/registry.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <utility>

namespace airlight {
namespace {

// Filled by the Registration objects during static initialization, in no
// particular order across files: sorted when first read.
std::vector<std::pair<int, MethodInfo (*)()>>& registrations() {
  static std::vector<std::pair<int, MethodInfo (*)()>> all;
  return all;
}

}  // namespace

kit::Registration::Registration(int order, MethodInfo (*info)()) { registrations().emplace_back(order, info); }

Trial kit::high_quality_trial(std::vector<std::string> settings, const std::string& left) {
  return {"high quality", std::move(settings), Trial::Measure::rel_rmse, 0.03,
          left + "; 3 % is issue 25's bound for sampling methods at high quality"};
}

Trial kit::reduced_trial(const std::string& method) {
  return {"half scale", {"scale=1/2"}, Trial::Measure::rel_rmse, 0.10,
          "at 32×24 a coarse pixel is a twelfth of the image's height, and an edge of the light within one is "
          "smoothed where its neighbours agree: seeds 0–15 at most 0.072 (interleaved, seed 7), 0.059 for the "
          "others, outside the bracket of the reference and the method at full scale (docs/decisions.md, "
          "reduced resolution)",
          {method, {}}};
}

const std::vector<MethodInfo>& registered_methods() {
  static const std::vector<MethodInfo> all = [] {
    auto sorted = registrations();
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<MethodInfo> infos;
    for (const auto& [order, info] : sorted) infos.push_back(info());
    return infos;
  }();
  return all;
}

const MethodInfo& find_method(const std::string& name, const std::string& source) {
  for (const auto& m : registered_methods())
    if (m.name == name) return m;
  std::string known;
  for (const auto& m : registered_methods()) known += (known.empty() ? "" : ", ") + m.name;
  throw InputError(source, name, "unknown method (known: " + known + ")");
}

Image select_pass(const FrameImages& frame, Pass pass) {
  if (pass == Pass::airlight) return frame.airlight;
  if (pass == Pass::surface) return frame.surface;
  Image composite = frame.surface;  // L = L_surf·T(d) + L_air (docs/design.md §1)
  for (size_t i = 0; i < composite.pixels.size(); ++i) composite.pixels[i] += frame.airlight.pixels[i];
  return composite;
}

}  // namespace airlight
