#include "scene/gobo_patterns.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/vec2.hpp>

namespace airlight::scene_gobo {
namespace {

constexpr int kSubsamples = 4;  // per texel and axis: 16 samples estimate each texel's area

// The image of `pattern`, a function of (u, v) in [0, 1]² with v = 1 the top
// row (optics::gobo_uv's convention), each texel the mean over its footprint.
template <class Pattern>
Image rasterize(int width, int height, Pattern pattern) {
  Image image(width, height);
  const float step = 1.0f / kSubsamples;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      glm::vec3 sum(0.0f);
      for (int j = 0; j < kSubsamples; ++j)
        for (int i = 0; i < kSubsamples; ++i) {
          const glm::vec2 uv((x + (i + 0.5f) * step) / width, 1.0f - (y + (j + 0.5f) * step) / height);
          sum += pattern(uv);
        }
      image.at(x, y) = sum / float(kSubsamples * kSubsamples);
    }
  return image;
}

// The stained glass's layout, in (u, v) units.
constexpr float kFrame = 0.04f;  // lead border
constexpr float kLead = 0.012f;  // half-width of a lead line
constexpr glm::vec2 kRoseCentre(0.5f, 0.70f);
constexpr float kRoseRadius = 0.24f, kEyeRadius = 0.08f;
constexpr int kPetals = 8, kColumns = 4, kRows = 6;

const glm::vec3 kLeadColor(0.0f);
const glm::vec3& ruby() { return glass_colors[0]; }
const glm::vec3& cobalt() { return glass_colors[1]; }
const glm::vec3& amber() { return glass_colors[2]; }

// Inside the rose, `d` from its centre: an amber eye and petals alternating
// ruby and cobalt, held by two lead circles and radial spokes.
glm::vec3 rose(glm::vec2 d) {
  const float r = glm::length(d);
  if (std::fabs(r - kRoseRadius) < kLead || std::fabs(r - kEyeRadius) < kLead) return kLeadColor;
  if (r < kEyeRadius) return amber();
  // The angle from the top, mirrored so that the two halves match.
  const float sector = glm::two_pi<float>() / kPetals;
  const float angle = std::atan2(std::fabs(d.x), d.y);
  const float off_spoke = std::fabs(angle - sector * std::round(angle / sector));
  if (r * std::sin(off_spoke) < kLead) return kLeadColor;
  return int(angle / sector) % 2 == 0 ? ruby() : cobalt();
}

// The rectangular panes inside the border: a kColumns × kRows lattice of lead,
// coloured in diagonal bands mirrored about the vertical centre line.
glm::vec3 pane(glm::vec2 uv) {
  const glm::vec2 span(1.0f - 2.0f * kFrame);
  const glm::vec2 cells = (uv - kFrame) / span * glm::vec2(kColumns, kRows);
  const glm::vec2 to_line = glm::abs(cells - glm::round(cells)) * span / glm::vec2(kColumns, kRows);
  if (glm::min(to_line.x, to_line.y) < kLead) return kLeadColor;
  const int column = std::clamp(int(cells.x), 0, kColumns - 1);
  const int row = std::clamp(int(cells.y), 0, kRows - 1);
  const int mirrored = std::min(column, kColumns - 1 - column);
  return glass_colors[size_t(mirrored + row) % glass_colors.size()];
}

glm::vec3 stained_glass_at(glm::vec2 uv) {
  if (std::min({uv.x, uv.y, 1.0f - uv.x, 1.0f - uv.y}) < kFrame) return kLeadColor;
  const glm::vec2 d = uv - kRoseCentre;
  return glm::length(d) < kRoseRadius + kLead ? rose(d) : pane(uv);
}

}  // namespace

Image polka_dots(int size, int grid, float fill) {
  return rasterize(size, size, [=](glm::vec2 uv) {
    const glm::vec2 from_centre = glm::fract(uv * float(grid)) - 0.5f;  // in lattice pitches
    return glm::vec3(glm::length(from_centre) < 0.5f * fill ? 1.0f : 0.0f);
  });
}

Image stained_glass(int width, int height) { return rasterize(width, height, stained_glass_at); }

}  // namespace airlight::scene_gobo
