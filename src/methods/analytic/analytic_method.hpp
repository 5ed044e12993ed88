#pragma once
#include <airlight/method.hpp>

namespace airlight::methods {

// analytic (DESIGN §3; Sun et al. 2005 via Kingston 4.2): per pixel, the
// closed-form unoccluded airlight of every light up to the G-buffer distance,
// with Sun et al.'s F(u, v) from a table or integrated in the shader. No
// volumetric shadows.
MethodInfo analytic_method();

}  // namespace airlight::methods
