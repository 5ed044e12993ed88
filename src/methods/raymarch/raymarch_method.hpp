#pragma once
#include <airlight/method.hpp>

namespace airlight::methods {

// raymarch (DESIGN §3; Tóth 2009, Kingston 4.1): per-pixel ray marching over the
// G-buffer distance with shadow-map visibility, optionally jittered, in even
// steps or equiangular about each point and spot light (Kulla & Fajardo 2012).
MethodInfo raymarch_method();

}  // namespace airlight::methods
