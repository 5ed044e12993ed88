// The viewer's background reference (reference_job.hpp) without a window: a job
// runs to the reference's own images while this thread polls it, a running job
// cancels, and a job destroyed while it runs gives way to a new one (the
// viewer's restart on a new view). scripts/tsan runs these under ThreadSanitizer.
#include "view/reference_job.hpp"

#include <airlight/scene.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <memory>
#include <thread>

namespace airlight::view {
namespace {

// Polls `done` as the viewer's frame loop does; false after `seconds`.
bool wait_for(const std::function<bool()>& done, double seconds = 300.0) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (!done()) {
    if (std::chrono::steady_clock::now() > end) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return true;
}

const Scene& scene() {
  static const Scene s = builtin_scene("teapot_spot");
  return s;
}

// A size the reference takes a while over, so a job is caught running.
constexpr int large_width = 320, large_height = 240;
constexpr int small_width = 24, small_height = 18;

void expect_finished_with_the_reference(const ReferenceJob& job) {
  ASSERT_TRUE(wait_for([&] { return job.finished(); }));
  EXPECT_EQ(job.error(), "");
  EXPECT_EQ(job.progress(), 1.0f);
  EXPECT_GT(job.seconds(), 0.0);
  // Each pixel is computed alone, so the job's arena and this thread's agree bit for bit.
  const reference::Images expected = reference::render(scene(), small_width, small_height);
  EXPECT_EQ(job.images().airlight.pixels, expected.airlight.pixels);
  EXPECT_EQ(job.images().surface.pixels, expected.surface.pixels);
}

TEST(ReferenceJob, FinishesWithTheReferencesImages) {
  const ReferenceJob job(scene(), small_width, small_height);
  expect_finished_with_the_reference(job);
}

TEST(ReferenceJob, CancelStopsARunningJob) {
  ReferenceJob job(scene(), large_width, large_height);
  ASSERT_TRUE(wait_for([&] { return job.progress() > 0.0f; }));
  job.cancel();
  ASSERT_TRUE(wait_for([&] { return job.finished(); }));
  EXPECT_EQ(job.error(), "cancelled");
  EXPECT_LT(job.progress(), 1.0f);
}

TEST(ReferenceJob, ANewJobReplacesARunningOne) {
  auto job = std::make_unique<ReferenceJob>(scene(), large_width, large_height);
  ASSERT_TRUE(wait_for([&] { return job->progress() > 0.0f; }));
  EXPECT_FALSE(job->finished());
  job = std::make_unique<ReferenceJob>(scene(), small_width, small_height);  // cancels and joins the old one
  expect_finished_with_the_reference(*job);
}

}  // namespace
}  // namespace airlight::view
