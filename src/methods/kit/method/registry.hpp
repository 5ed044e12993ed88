#pragma once
// Registration from inside a method's folder (docs/design.md §3): a method's
// .cpp ends with AIRLIGHT_REGISTER_METHOD(order, info), `info` a function
// returning its MethodInfo and `order` its place in `airlight list methods`
// (the order of docs/design.md §3). Nothing outside the folder names it.
#include <airlight/method.hpp>

namespace airlight::kit {

struct Registration {
  Registration(int order, MethodInfo (*info)());
};

}  // namespace airlight::kit

#define AIRLIGHT_REGISTER_METHOD(order, info) \
  [[maybe_unused]] static const ::airlight::kit::Registration airlight_registration_##info{order, info}
