#pragma once
// A buffer of T for what a frame makes (triangles, vertices, indices): made
// again only when a frame needs more than it holds, so that a frame of the
// usual size allocates nothing. Made again, it holds `growth` × the need (at
// least one T, so that it can be bound), and its contents are gone.
#include "gpu/gl.hpp"

#include <algorithm>
#include <span>

namespace airlight::gpu {

template <class T>
class GrowingBuffer {
public:
  explicit GrowingBuffer(size_t growth = 1) : growth_(growth) {}

  // Room for `count` T. True if the buffer was made again: what was bound to the old one is stale.
  bool reserve(size_t count) {
    if (buffer_ && count <= capacity_) return false;
    capacity_ = std::max<size_t>(count, 1) * growth_;
    buffer_ = make_buffer(capacity_ * sizeof(T), nullptr);
    return true;
  }
  // `items` at the buffer's start (reserve's room first, and its answer).
  bool assign(std::span<const T> items) {
    const bool made = reserve(items.size());
    if (!items.empty()) glNamedBufferSubData(buffer_.id(), 0, items.size() * sizeof(T), items.data());
    return made;
  }
  // Lets the buffer go (as prepare() does for a new context): the next reserve makes one.
  void release() {
    buffer_.reset();
    capacity_ = 0;
  }

  const Buffer& buffer() const { return buffer_; }
  GLuint id() const { return buffer_.id(); }

private:
  size_t growth_;
  size_t capacity_ = 0;
  Buffer buffer_;
};

}  // namespace airlight::gpu
