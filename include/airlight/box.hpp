#pragma once
// An oriented box in world space: the scene's per-object bounding volumes (Nilsson §5.1),
// an axis-aligned box in the object's own coordinates carried by its transform.
#include <airlight/export.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace airlight {

struct AIRLIGHT_API OrientedBox {
  glm::vec3 center{0.0f};
  glm::mat3 axes{1.0f};   // columns: the box's unit, orthogonal axes
  glm::vec3 half{0.0f};   // half-sizes along them, > 0

  // Corner k (0..7): bit i of k picks the + side along axis i.
  glm::vec3 corner(int k) const {
    glm::vec3 p = center;
    for (int i = 0; i < 3; ++i) p += ((k >> i & 1) ? half[i] : -half[i]) * axes[i];
    return p;
  }
};

}  // namespace airlight
