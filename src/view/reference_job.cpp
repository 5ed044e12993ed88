#include "view/reference_job.hpp"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <oneapi/tbb/task_arena.h>

namespace airlight::view {

ReferenceJob::ReferenceJob(Scene posed, int width, int height)
    : width_(width), height_(height), worker_([this, scene = std::move(posed)] {
        const auto start = std::chrono::steady_clock::now();
        try {
          tbb::task_arena arena(std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1));
          arena.execute([&] { images_ = reference::render(scene, width_, height_, {}, &control_); });
        } catch (const reference::Cancelled&) {
          error_ = "cancelled";
        } catch (const std::exception& e) {
          error_ = e.what();
        }
        seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        finished_ = true;
      }) {}

ReferenceJob::~ReferenceJob() {
  cancel();
  worker_.join();
}

float ReferenceJob::progress() const {
  const long total = control_.total;
  return total > 0 ? static_cast<float>(control_.done) / static_cast<float>(total) : 0.0f;
}

namespace {

// FNV-1a over the bytes of plain values.
class Hash {
public:
  template <typename T>
  void add(const T& value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    for (unsigned char b : bytes) h_ = (h_ ^ b) * 0x100000001b3ull;
  }
  std::uint64_t value() const { return h_; }

private:
  std::uint64_t h_ = 0xcbf29ce484222325ull;
};

}  // namespace

std::uint64_t view_key(const FrameInputs& inputs, int width, int height) {
  Hash h;
  h.add(width);
  h.add(height);
  const Camera& c = inputs.camera;
  for (const glm::vec3& v : {c.position, c.look_at, c.up}) h.add(v);
  for (float f : {c.fov_y_deg, c.near, c.far}) h.add(f);
  for (const Light& l : inputs.lights) {
    h.add(l.type);
    for (const glm::vec3& v : {l.position, l.direction, l.intensity, l.irradiance, l.gobo_up}) h.add(v);
    h.add(l.cone_deg);
    h.add(l.edge_deg);
    h.add(l.gobo.get());  // gobos are the prepared scene's images: the pointer names one
    if (l.beam) {
      h.add(l.beam->origin);
      h.add(l.beam->size);
      h.add(l.beam->length);
    }
  }
  h.add(inputs.medium.sigma_s);
  h.add(inputs.medium.sigma_a);
  for (const PhaseLobe& lobe : inputs.medium.phase.lobes) {
    h.add(lobe.type);
    h.add(lobe.g);
    h.add(lobe.weight);
  }
  h.add(inputs.light_model.type);
  h.add(inputs.light_model.a0);
  h.add(inputs.light_model.a1);
  return h.value();
}

}  // namespace airlight::view
