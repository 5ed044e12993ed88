#pragma once
#include <airlight/method.hpp>

namespace airlight::methods {

// Dobashi, Yamamoto & Nishita 2000: virtual planes (methods/planes/).
MethodInfo planes_method();

}  // namespace airlight::methods
