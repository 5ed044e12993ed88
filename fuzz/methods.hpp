#pragma once
// The methods the option parsers' fuzz target knows: three of the registered ones
// with their settings as declared (every setting type among them), without the GPU
// code behind them, so the fuzz build needs no method. regressions_test.cpp holds
// them to the registered methods' declarations.
#include <airlight/method.hpp>
#include <vector>

namespace airlight::fuzz {

MethodInfo reference_info();
MethodInfo raymarch_info();
MethodInfo planes_info();

}  // namespace airlight::fuzz
