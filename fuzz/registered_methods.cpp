// The fuzz build's registry holds fuzz/methods.cpp's methods, in the registered order.
#include "methods.hpp"

#include "methods/kit/method/registry.hpp"

namespace {
using airlight::fuzz::planes_info;
using airlight::fuzz::raymarch_info;
using airlight::fuzz::reference_info;
}  // namespace

AIRLIGHT_REGISTER_METHOD(0, reference_info);
AIRLIGHT_REGISTER_METHOD(1, raymarch_info);
AIRLIGHT_REGISTER_METHOD(3, planes_info);
