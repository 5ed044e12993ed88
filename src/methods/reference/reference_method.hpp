#pragma once
#include <airlight/method.hpp>

namespace airlight::methods {

// The CPU ground truth (src/reference) behind the method contract.
MethodInfo reference_method();

}  // namespace airlight::methods
