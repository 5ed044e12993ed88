#pragma once
// Registration from inside a method's folder (docs/design.md §3): a method's
// .cpp ends with AIRLIGHT_REGISTER_METHOD(order, info), `info` a function
// returning its MethodInfo and `order` its place in `airlight list methods`
// (the order of docs/design.md §3). Nothing outside the folder names it.
#include <airlight/method.hpp>

#include <memory>
#include <string>
#include <vector>

namespace airlight::kit {

struct Registration {
  Registration(int order, MethodInfo (*info)());
};

// MethodInfo::create of a method made from its settings and `args`:
// create<Raymarch>(), create<PlaneMethod>(PlaneCut::gamma).
template <class M, class... Args>
auto create(Args... args) {
  return [args...](const Settings& s) -> std::unique_ptr<Method> { return std::make_unique<M>(s, args...); };
}

// A sampling method's "high quality" trial: its rRMSE at `settings` over its
// defaults within 3 % rRMSE (docs/design.md §6), `left` saying what error those settings leave.
Trial high_quality_trial(std::vector<std::string> settings, const std::string& left);
// The trial of a per-pixel method at scale = 1/2 (per_pixel_settings): its
// image against the bracket of the reference and its own at full scale, so
// that what is bounded is what the reduced resolution adds.
Trial reduced_trial(const std::string& method);

}  // namespace airlight::kit

#define AIRLIGHT_REGISTER_METHOD(order, info) \
  [[maybe_unused]] static const ::airlight::kit::Registration airlight_registration_##info{order, info}
