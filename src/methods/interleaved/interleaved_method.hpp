#pragma once
#include <airlight/method.hpp>

namespace airlight::methods {

// interleaved (DESIGN §3; Tóth 2009 §4.1): raymarch with the N samples spread
// over M×M pixel blocks, then a separable (optionally depth-aware) sum.
MethodInfo interleaved_method();

}  // namespace airlight::methods
