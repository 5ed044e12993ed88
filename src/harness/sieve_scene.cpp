#include "harness/sieve_scene.hpp"

#include "core/atomic_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/vec2.hpp>
#include <string>

namespace airlight::harness {
namespace {

constexpr int tiles = 10;                    // per side
constexpr double pitch = 0.24, tile = 0.16;  // metres: gaps of 8 cm between tiles
constexpr double lift = 8e-5;                // metres: 5× the beam tree's ε here (10⁻⁶ of the scene)

// a×b quads per tile, a ≤ b, as square as `quads` allows.
std::pair<long, long> tile_grid(long quads) {
  long a = std::max(1L, static_cast<long>(std::sqrt(static_cast<double>(quads))));
  while (quads % a != 0) --a;
  return {a, quads / a};
}

// One triangle with its own three vertices (OBJ counts them from 1), grown
// about its centre by 30 % and lifted by `lift` metres: it overlaps its
// neighbours, which lie at the other height, so no vertex or edge is shared
// (welding cannot join the triangles into one surface) and, seen from the
// light, no gap opens between them (the lift's parallax stays below the
// overlap up to 10⁶ triangles).
void triangle(std::string& text, long& count, const glm::dvec2 (&corners)[3], double lift) {
  constexpr double grow = 1.3;
  const glm::dvec2 centre = (corners[0] + corners[1] + corners[2]) / 3.0;
  char line[96];
  for (const glm::dvec2& c : corners) {
    const glm::dvec2 v = centre + grow * (c - centre);
    std::snprintf(line, sizeof line, "v %.6f %.6f %.6f\n", v.x, lift, v.y);
    text += line;
  }
  std::snprintf(line, sizeof line, "f %ld %ld %ld\n", count + 1, count + 2, count + 3);
  text += line;
  count += 3;
}

// Each tile's a×b quads as two triangles each, in the sieve's own plane y = 0
// centred on the origin (the scene's transform places it).
std::string sieve_obj(long triangles) {
  const auto [a, b] = tile_grid(triangles / (2L * tiles * tiles));
  std::string text = "# airlight sieve: " + std::to_string(triangles) + " triangles\n";
  text.reserve(static_cast<size_t>(triangles) * 100);
  long vertices = 0;
  for (int ti = 0; ti < tiles; ++ti)
    for (int tj = 0; tj < tiles; ++tj) {
      const glm::dvec2 corner = (glm::dvec2(ti, tj) - tiles / 2.0) * pitch + (pitch - tile) / 2.0;
      const glm::dvec2 step(tile / static_cast<double>(a), tile / static_cast<double>(b));
      for (long j = 0; j < b; ++j)
        for (long i = 0; i < a; ++i) {
          const glm::dvec2 p = corner + glm::dvec2(i, j) * step, dx(step.x, 0.0), dz(0.0, step.y);
          triangle(text, vertices, {p, p + dz, p + dx}, 0.0);
          triangle(text, vertices, {p + dx, p + dz, p + dx + dz}, lift);
        }
    }
  return text;
}

// A spot 2 m above the sieve's centre, the sieve tilted 15° about x, the
// camera to the side of the shafts between it and the floor.
constexpr const char* scene_json = R"({
  "format": "airlight-scene/1",
  "name": "sieve",
  "camera": {"position": [0, 2.2, 7.5], "look_at": [0, 1.6, 0], "fov_y_deg": 45, "far": 30},
  "medium": {"scattering": 0.08, "absorption": 0.01, "phase": {"type": "henyey_greenstein", "g": 0.3}},
  "lights": [
    {"type": "spot", "position": [0, 4.5, 0], "direction": [0, -1, 0], "intensity": 200, "cone_deg": 35}],
  "objects": [
    {"shape": "box", "min": [-6, -0.2, -6], "max": [6, 0, 6], "albedo": 0.6, "name": "floor"},
    {"mesh": "sieve.obj", "translate": [0, 2.5, 0], "rotate_deg": [15, 0, 0], "albedo": 0.7, "name": "sieve"}]
}
)";

}  // namespace

long sieve_triangles(long triangles) {
  constexpr long step = 2L * tiles * tiles;
  return std::max(step, triangles / step * step);
}

std::filesystem::path write_sieve_scene(const std::filesystem::path& dir, long triangles) {
  write_text_file(dir / "sieve.obj", sieve_obj(sieve_triangles(triangles)));
  const std::filesystem::path scene = dir / "sieve.json";
  write_text_file(scene, scene_json);
  return scene;
}

}  // namespace airlight::harness
