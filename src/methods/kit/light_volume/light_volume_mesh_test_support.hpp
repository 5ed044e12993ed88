#pragma once
// What light_volume_mesh_test.cpp builds its cases from: random shadow maps
// given to the frame as an engine's (a spot's perspective map and a sun's
// orthographic one in window depth, a point light's cube of distances), the
// frame that imports them, the maps as imported read back, and the read-back
// mesh's closure, signed volume and parity.
#include "methods/kit/frame/scene_frame.hpp"
#include "methods/kit/light_volume/light_volume_mesh.hpp"

#include <airlight/engine.hpp>
#include <airlight/scene.hpp>
#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace airlight::kit::volume_test {

using Depth = LightVolumeMesh::Depth;

constexpr int width = 16, height = 12;

enum class Kind { spot, point, directional };
inline const char* name(Kind k) { return k == Kind::spot ? "spot" : k == Kind::point ? "point" : "directional"; }

struct Rect {
  double x0, y0, x1, y1, value;  // NDC (or face st) box and its value; value < 0: no occluder
};

// The rig: a scene, its light, the engine's map and the frame.
struct Rig {
  Kind kind;
  int size;
  Scene scene;
  EngineShadow shadow;
  gpu::Texture texture;
  glm::dmat4 matrix{1.0};  // 2D: the engine's light matrix (airlight's shadow_matrix)
  SceneFrame frame;
  std::vector<float> stored;  // the frame's map as imported: S² (2D) or 6·S² (cube, face-major)

  // A box under the light, and the engine's random map of `s`² texels (a tilted base, boxes nearer the light, and boxes with no occluder).
  Rig(Kind k, int s, unsigned seed);

  // The engine's 2D map: window depth ([−1, 1] range) of view depth base + tilt, or the boxes' depths.
  void upload_2d(const std::vector<Rect>& rects, double base);
  // The engine's cube of distances: per face a tilted base and boxes, so that
  // faces meet with steps along the seams too.
  void upload_cube(std::mt19937& rng);

  const Light& light() const { return scene.lights[0]; }

  // The frame with the camera at `eye`; the imported map read back.
  void render(const glm::vec3& eye);

  glm::dvec3 eye() const { return glm::dvec3(scene.camera.position); }
  // How far from the eye the frame sees: the far plane along the corner rays.
  double reach() const;
  glm::dvec3 direction() const;
  // The depths the build clamps to (light_volume_mesh.cpp), as the shader holds them (float).
  float far_depth() const;
  float cap_depth() const;
  double clamped(double v) const;
  // The texel mesh's depth for a texel: as far as the shadow test calls lit
  // (scene.glsl's shadow_visibility: the stored depth, no bias).
  double texel(int face, int i, int j) const;

  // The world point whose map NDC is (x, y) and depth (distance from the light, or depth along the travel) d.
  glm::dvec3 point_2d(double x, double y, double d) const;
};

// ---- the read-back mesh ----------------------------------------------------------------

struct Triangle {
  glm::dvec3 a, b, c;
};

std::vector<Triangle> triangles(const std::vector<CountedTriangle>& records);

struct Closure {
  size_t boundary = 0, inconsistent = 0, other = 0, degenerate = 0, vertices = 0, uncancelled_stretches = 0;
};

// The lines from the light a mesh's vertices lie on (for a directional light,
// the lines along its travel): a vertex's line found by its direction from
// the light (or its foot on the plane across the travel) to within `tolerance`
// — far below the grid's spacing, far above float's rounding — and where on
// it (distance from the light, or depth along the travel). The light's own
// position lies on every line.
struct Lines {
  glm::dvec3 light, travel;
  bool directional;
  double tolerance;
  std::map<std::array<long long, 3>, int> cells;
  int count = 0;

  std::pair<int, double> line(const glm::dvec3& p);
};

// Corners welded by their exact bits; each undirected edge must appear once in
// each direction, unless both its ends lie on one line from the light: there
// the edges, as signed stretches of the line, must cancel.
Closure closure(const std::vector<CountedTriangle>& records, Lines lines);

// Lines for a light: 10⁻⁵ rad between directions, 10⁻⁴ m between a
// directional light's lines (the grids' spacings are above 10⁻³ rad and 0.1 m,
// float's rounding of these coordinates below 10⁻⁶).
Lines lines_of(const Light& light);

double signed_volume(const std::vector<Triangle>& mesh, const glm::dvec3& origin);

// Crossings of the ray x + t·dir (t > 0) with the mesh (Möller–Trumbore, double): odd = inside.
bool inside(const std::vector<Triangle>& mesh, const glm::dvec3& x, const glm::dvec3& dir);

glm::dvec3 random_direction(std::mt19937& rng);

// Parity from two random rays; -1 when they disagree (x within rounding of the surface).
int parity(const std::vector<Triangle>& mesh, const glm::dvec3& x, std::mt19937& rng);

// A mesh at `resolution` and `depth`, prepared and built on the rig's frame.
std::unique_ptr<LightVolumeMesh> built(Rig& rig, int resolution, Depth depth);

// A record as lit_intervals.glsl reads it: light 0, weight 1, a unit normal,
// or, for a triangle with no area, no normal (no ray crosses it:
// crossings.frag.glsl's t is not finite).
bool well_formed(const CountedTriangle& t);

}  // namespace airlight::kit::volume_test
