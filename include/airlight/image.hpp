#pragma once
// Linear float RGB images, row 0 at the top.
#include <airlight/export.hpp>
#include <glm/vec3.hpp>
#include <vector>

namespace airlight {

struct AIRLIGHT_API Image {
  int width = 0, height = 0;
  std::vector<glm::vec3> pixels;  // width * height, row-major, top row first

  Image() = default;
  Image(int w, int h, glm::vec3 fill = glm::vec3(0.0f))
      : width(w), height(h), pixels(static_cast<size_t>(w) * h, fill) {}
  glm::vec3& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  const glm::vec3& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
  bool empty() const { return pixels.empty(); }
};

}  // namespace airlight
