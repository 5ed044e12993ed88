// One frame of every registered method, prepared, rendered through all of its
// passes and read back. The sanitizer suite leaves each method's quality table
// to the release suite (README "Tests and their budget"); this is what it keeps
// of every method even then, with the scene it was prepared with gone before
// the frame. On teapot_spot (a spot, its 2D shadow map, a
// closed caster, a floor): a scene of every light type and a bounded volume
// costs sv_march alone 100 s of program compiling on llvmpipe with Mesa's
// shader cache off, against 7 s here, and each method's own tests cover those.
#include "gpu/program.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace airlight::kit::test {
namespace {

double mean(const Image& image) {
  double sum = 0.0;
  for (const auto& p : image.pixels) sum += p.r + p.g + p.b;
  return sum / (3.0 * static_cast<double>(image.pixels.size()));
}

// GoogleTest evaluates this when it registers the tests, after every method's
// registration has run.
std::vector<std::string> method_names() {
  std::vector<std::string> names;
  for (const MethodInfo& info : registered_methods()) names.push_back(info.name);
  return names;
}

class EveryMethod : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryMethod, RendersAFrameThroughEveryPass) {
  const MethodInfo& info = find_method(GetParam());
  const Scene scene = builtin_scene("teapot_spot");
  // The contract does not ask the caller to keep the scene after prepare(): the
  // one it was prepared with is gone before the frame (a read of it is ASan's).
  const std::unique_ptr<Method> method = [&] {
    const Scene temporary = scene;
    return prepared(info, temporary, {});
  }();
  const FrameImages frame = airlight::render(*method, scene, 32, 24);
  EXPECT_TRUE(all_finite_and_non_negative(frame.airlight));
  EXPECT_TRUE(all_finite_and_non_negative(frame.surface));
  // The spot's cone and the lit floor fill much of the view: a pass that did
  // nothing shows as black (the reference's means at this size: 0.069 and 0.078).
  EXPECT_GT(mean(frame.airlight), 0.01);
  EXPECT_GT(mean(frame.surface), 0.01);
  if (info.name != "reference") {
    EXPECT_FALSE(frame.times.empty());  // the GPU methods time each pass they run
    // What a frame links ahead has the defines it then asks for (GpuMethod::link_ahead).
    EXPECT_EQ(gpu::programs_linking(), 0) << "a program linked ahead was not the one the frame used";
  }
}

TEST(EveryMethodList, HoldsTheReferenceAndTheTenGpuMethods) { EXPECT_GE(method_names().size(), 11u); }

INSTANTIATE_TEST_SUITE_P(Registered, EveryMethod, ::testing::ValuesIn(method_names()),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace airlight::kit::test
