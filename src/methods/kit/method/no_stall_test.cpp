// A frame never waits for its own queries (docs/design.md §2, gpu/): on the
// GPU's timer path — timestamp queries, forced here on llvmpipe, whose wall
// clock would read no query at all — neither render_frame nor numbers() reads
// a query by waiting, for the march and for counted crossings (whose draws
// count their fragments with a query too); numbers() name the frame their
// times are of, and once the GPU is idle that is the last one.
#include "gpu/query.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace airlight::kit::test {
namespace {

// Timestamp queries for the PassTimers made in its lifetime.
struct TimestampQueries {
  TimestampQueries() { gpu::force_timestamp_queries(true); }
  ~TimestampQueries() { gpu::force_timestamp_queries(false); }
};

std::vector<std::string> pass_names(const std::vector<PassTime>& times) {
  std::vector<std::string> names;
  for (const PassTime& t : times) names.push_back(t.pass);
  return names;
}

class NoStall : public ::testing::TestWithParam<std::string> {};

TEST_P(NoStall, FramesNeverWaitForTheirQueriesAndNumbersNameTheirFrame) {
  const TimestampQueries timestamps;
  const Scene scene = builtin_scene("teapot_spot");
  const auto method = prepared(find_method(GetParam()), scene, {});
  EXPECT_EQ(method->numbers().frame, -1);  // no frame yet
  const FrameInputs inputs = frame_inputs(scene, 32, 24);
  constexpr int frames = 6;  // more than the timer keeps in flight (4): the oldest are dropped unread
  std::int64_t newest = -1;
  for (int frame = 0; frame < frames; ++frame) {
    const std::int64_t waits = gpu::blocking_query_reads();
    method->render_frame(inputs);
    const FrameNumbers numbers = method->numbers();
    EXPECT_EQ(gpu::blocking_query_reads(), waits) << GetParam() << " frame " << frame;
    // The newest frame the GPU has finished: never one not yet rendered, never older than the last shown.
    EXPECT_LE(numbers.frame, frame);
    EXPECT_GE(numbers.frame, newest);
    newest = numbers.frame;
  }
  glFinish();
  const FrameNumbers idle = method->numbers();
  EXPECT_EQ(idle.frame, frames - 1);  // the GPU is idle: the last frame's
  const FrameImages last = method->read_back();
  EXPECT_EQ(pass_names(idle.times), pass_names(last.times));
  EXPECT_FALSE(idle.times.empty());
}

// raymarch: the frame's and the march's passes alone; shadow_planes: counted
// crossings (CountedDraw's fragment query); light_volume: the mesh's own timer.
INSTANTIATE_TEST_SUITE_P(Methods, NoStall, ::testing::Values("raymarch", "shadow_planes", "light_volume"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace airlight::kit::test
