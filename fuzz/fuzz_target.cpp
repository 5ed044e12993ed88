// A libFuzzer target: AIRLIGHT_FUZZ_TARGET names the input of fuzz/inputs.cpp it feeds.
#include "inputs.hpp"

#include "core/warning.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ostream>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // Warnings are part of what a loader does, but a million of them say nothing here.
  static std::ostream discard(nullptr);
  airlight::set_warning_stream(&discard);
  if (!airlight::fuzz::target(AIRLIGHT_FUZZ_TARGET)) {
    std::fprintf(stderr, "no fuzz input named %s\n", AIRLIGHT_FUZZ_TARGET);
    std::abort();
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const airlight::fuzz::Outcome run = airlight::fuzz::target(AIRLIGHT_FUZZ_TARGET);
  run(std::string(reinterpret_cast<const char*>(data), size));
  return 0;
}
