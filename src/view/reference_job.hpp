#pragma once
// The error view's reference (issue 16 item 4): the CPU reference renders the
// scene as posed now, at the window's size, on a worker thread inside a task
// arena one core short of the machine, so the window keeps drawing while it
// runs. Destroying the job (a new view, the error view turned off) cancels it:
// tiles not yet started are skipped and the worker is joined. Every member the
// worker writes is read only after finished() (an atomic), so the window's
// thread may poll progress() and finished() at any time (scripts/tsan).
#include "reference/reference.hpp"

#include <airlight/method.hpp>
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

namespace airlight::view {

class ReferenceJob {
public:
  ReferenceJob(Scene posed, int width, int height);
  ~ReferenceJob();
  ReferenceJob(const ReferenceJob&) = delete;
  ReferenceJob& operator=(const ReferenceJob&) = delete;

  float progress() const;  // 0 … 1, by tiles
  // Skips the tiles not yet started: finished() follows with error() "cancelled".
  void cancel() { control_.cancel = true; }
  bool finished() const { return finished_; }
  // After finished(): the images, or why there are none.
  const reference::Images& images() const { return images_; }
  const std::string& error() const { return error_; }
  double seconds() const { return seconds_; }

private:
  const int width_, height_;
  reference::Control control_;
  reference::Images images_;
  std::string error_;
  double seconds_ = 0.0;
  std::atomic<bool> finished_{false};
  std::thread worker_;  // last: it starts once everything it writes exists
};

// A hash of everything the viewer lets change in a frame's image: camera,
// lights, medium, light model and size (the scene's meshes are fixed). A new
// key means the reference no longer shows this view.
std::uint64_t view_key(const FrameInputs& inputs, int width, int height);

}  // namespace airlight::view
