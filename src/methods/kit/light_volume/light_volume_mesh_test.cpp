// The light volume mesh (methods/kit/light_volume/light_volume_mesh.hpp) from random shadow
// maps with discontinuities and "no occluder" regions, given to the frame as an
// engine's maps (<airlight/engine.hpp>: a spot's perspective map and a sun's
// orthographic one in window depth, a point light's cube of distances), so
// that the mesh is built from what the frame imported into its own textures —
// which the tests read back and hold the mesh to:
// 1. closed: corners welded by exact position, every edge used by exactly two
//    triangles in opposite directions, or, along a line from the light (the
//    texel mesh's walls meet there at several depths), edges that cancel as
//    stretches of that line (spot, cube across its seams, directional with its
//    skirt; R = 32, 64 and the map's size; every depth mode);
// 2. outward: positive signed volume, and random points inside / outside the
//    stored surface are inside / outside the read-back mesh by ray parity;
// 3. eye counts: 0 inside, 1 outside, and the mesh's parity at random eyes;
// 4. nearest ≤ texel ≤ farthest at every vertex.
#include "core/metrics.hpp"
#include "geometry/camera.hpp"
#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "gpu/gl.hpp"
#include "methods/kit/light_volume/light_volume_mesh.hpp"
#include "methods/kit/frame/scene_frame.hpp"
#include "methods/kit/frame/shadows/shadow_projection.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <airlight/engine.hpp>
#include <airlight/method.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <memory>
#include <random>
#include <unordered_map>
#include <vector>

namespace airlight::kit {
namespace {

using Depth = LightVolumeMesh::Depth;

constexpr int width = 16, height = 12;

enum class Kind { spot, point, directional };
const char* name(Kind k) { return k == Kind::spot ? "spot" : k == Kind::point ? "point" : "directional"; }

// ---- random maps -------------------------------------------------------------------

struct Rect {
  double x0, y0, x1, y1, value;  // NDC (or face st) box and its value; value < 0: no occluder
};

// A tilted base, boxes nearer the light, and boxes with no occluder.
std::vector<Rect> random_rects(std::mt19937& rng, int count, double near_lo, double near_hi, int none) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), v(near_lo, near_hi), size(0.1, 0.6);
  std::vector<Rect> rects;
  for (int k = 0; k < count + none; ++k) {
    const double x = u(rng), y = u(rng), w = size(rng), h = size(rng);
    rects.push_back({x - w / 2, y - h / 2, x + w / 2, y + h / 2, k < count ? v(rng) : -1.0});
  }
  return rects;
}

double map_value(const std::vector<Rect>& rects, double base, double x, double y) {
  double value = base;
  for (const Rect& r : rects)
    if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) value = r.value;  // later boxes cover earlier ones
  return value;
}

// ---- the rig: a scene, its light, the engine's map and the frame --------------------

struct Rig {
  Kind kind;
  int size;
  Scene scene;
  EngineShadow shadow;
  gpu::Texture texture;
  glm::dmat4 matrix{1.0};  // 2D: the engine's light matrix (airlight's shadow_matrix)
  SceneFrame frame;
  std::vector<float> stored;  // the frame's map as imported: S² (2D) or 6·S² (cube, face-major)

  Rig(Kind k, int s, unsigned seed) : kind(k), size(s) {
    std::mt19937 rng(seed);
    scene.name = "light_volume";
    scene.camera.position = {3.0f, 4.0f, 12.0f};
    scene.camera.look_at = {0.0f, 1.0f, 0.0f};
    scene.camera.far = 30.0f;
    scene.medium.sigma_s = Color(0.05f);
    scene.meshes.push_back(test::box({-1, 0, -1}, {1, 1, 1}, Color(0.5f)));
    if (kind == Kind::spot) {
      scene.lights.push_back(test::make_light(LightType::spot, {0, 10, 0}, {0, -1, 0}, 100.0f, 30.0f));
      const glm::dvec3 l(0, 10, 0);
      shadow.view = glm::mat4(glm::lookAt(l, l + glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1)));
      shadow.projection = glm::mat4(glm::perspective(glm::radians(70.0), 1.0, 0.5, 40.0));
      upload_2d(random_rects(rng, 10, 3.0, 8.0, 3), 9.0);
    } else if (kind == Kind::directional) {
      const glm::dvec3 dir = glm::normalize(glm::dvec3(0.2, -1.0, 0.1));
      scene.lights.push_back(test::make_light(LightType::directional, {}, glm::vec3(dir), 1.0f));
      shadow.view = glm::mat4(glm::lookAt(-20.0 * dir, glm::dvec3(0.0), glm::dvec3(0, 0, 1)));
      shadow.projection = glm::mat4(glm::ortho(-10.0, 10.0, -10.0, 10.0, 1.0, 40.0));
      upload_2d(random_rects(rng, 10, 8.0, 18.0, 3), 20.0);
    } else {
      scene.lights.push_back(test::make_light(LightType::point, {0, 3, 0}, {0, -1, 0}, 100.0f));
      upload_cube(rng);
    }
    texture_id();
    frame.prepare(scene);
  }

  void texture_id() { shadow.texture = texture.id(); }

  // The engine's 2D map: window depth ([−1, 1] range) of view depth base + tilt, or the boxes' depths.
  void upload_2d(const std::vector<Rect>& rects, double base) {
    matrix = glm::dmat4(shadow.projection) * glm::dmat4(shadow.view);
    const glm::dmat4 p(shadow.projection);
    std::vector<float> depth(static_cast<size_t>(size) * size);
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const double x = 2.0 * (i + 0.5) / size - 1.0, y = 2.0 * (j + 0.5) / size - 1.0;
        const double v = map_value(rects, base + 2.0 * x + 1.0 * y, x, y);
        const glm::dvec4 clip = p * glm::dvec4(0.0, 0.0, -v, 1.0);
        depth[static_cast<size_t>(j) * size + i] = v < 0.0 ? 1.0f : static_cast<float>(0.5 * clip.z / clip.w + 0.5);
      }
    texture = gpu::make_texture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, size, size);
    glTextureSubImage2D(texture.id(), 0, 0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    shadow.kind = EngineShadow::Kind::map;
  }

  // The engine's cube of distances: per face a tilted base and boxes, so that
  // faces meet with steps along the seams too.
  void upload_cube(std::mt19937& rng) {
    texture = gpu::make_texture(GL_TEXTURE_CUBE_MAP, GL_R32F, size, size);
    std::vector<float> distance(static_cast<size_t>(size) * size);
    for (int face = 0; face < 6; ++face) {
      const std::vector<Rect> rects = random_rects(rng, 5, 1.0, 4.0, 1);
      const double base = 6.0 + 0.5 * face;
      for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
          const double s = 2.0 * (i + 0.5) / size - 1.0, t = 2.0 * (j + 0.5) / size - 1.0;
          const double d = map_value(rects, base + s - 0.5 * t, s, t);
          distance[static_cast<size_t>(j) * size + i] = d < 0.0 ? FLT_MAX : static_cast<float>(d);
        }
      glTextureSubImage3D(texture.id(), 0, 0, 0, face, size, size, 1, GL_RED, GL_FLOAT, distance.data());
    }
    shadow.kind = EngineShadow::Kind::cube;
    shadow.stores = EngineShadow::Stores::distance;
  }

  const Light& light() const { return scene.lights[0]; }

  // The frame with the camera at `eye`; the imported map read back.
  void render(const glm::vec3& eye) {
    scene.camera.position = eye;
    scene.camera.look_at = eye + glm::vec3(0.3f, -0.2f, -1.0f);
    EngineFrame engine;
    engine.shadows = {shadow};
    PassTimer timer;
    frame.render(frame_inputs(scene, width, height), FrameSettings{size, 1.0f}, &engine, {true, false}, timer);
    frame.bind();
    const bool cube = kind == Kind::point;
    GLint id = 0;
    glActiveTexture(GL_TEXTURE0 + (cube ? binding::shadow_cubes : binding::shadow_maps));
    glGetIntegerv(cube ? GL_TEXTURE_BINDING_CUBE_MAP_ARRAY : GL_TEXTURE_BINDING_2D_ARRAY, &id);
    glActiveTexture(GL_TEXTURE0);
    stored.assign(static_cast<size_t>(size) * size * (cube ? 6 : 1), 0.0f);
    glGetTextureImage(static_cast<GLuint>(id), 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(stored.size() * sizeof(float)),
                      stored.data());
  }

  glm::dvec3 eye() const { return glm::dvec3(scene.camera.position); }
  // How far from the eye the frame sees: the far plane along the corner rays.
  double reach() const { return geometry::corner_distance(scene.camera, double(width) / height, scene.camera.far); }
  glm::dvec3 direction() const { return glm::dvec3(glm::normalize(light().direction)); }
  // The depths the build clamps to (light_volume_mesh.cpp), as the shader holds them (float).
  float far_depth() const {
    if (kind == Kind::directional) return static_cast<float>(glm::dot(eye(), direction()) + 2.0 * reach());
    return static_cast<float>(2.0 * (glm::length(eye() - glm::dvec3(light().position)) + reach()));
  }
  float cap_depth() const { return static_cast<float>(glm::dot(eye(), direction()) - 2.0 * reach()); }
  double clamped(double v) const {
    const double lo = kind == Kind::directional ? cap_depth() : 0.0;
    return std::min(std::max(v, lo), static_cast<double>(far_depth()));
  }
  // The texel mesh's depth for a texel: as far as the shadow test calls lit
  // (scene.glsl's shadow_visibility: the stored depth, no bias).
  double texel(int face, int i, int j) const {
    return clamped(stored[(static_cast<size_t>(face) * size + j) * size + i]);
  }

  // The world point whose map NDC is (x, y) and depth (distance from the light, or depth along the travel) d.
  glm::dvec3 point_2d(double x, double y, double d) const {
    const glm::dmat4 inverse = glm::inverse(matrix);
    const glm::dvec4 a = inverse * glm::dvec4(x, y, -1.0, 1.0), b = inverse * glm::dvec4(x, y, 1.0, 1.0);
    const glm::dvec3 near(a / a.w), far_point(b / b.w);
    const glm::dvec3 along = glm::normalize(far_point - near);
    if (kind == Kind::spot) return glm::dvec3(light().position) + d * along;
    return near + (d - glm::dot(near, direction())) / glm::dot(along, direction()) * along;
  }
};

// ---- the read-back mesh ----------------------------------------------------------------

struct Triangle {
  glm::dvec3 a, b, c;
};

std::vector<Triangle> triangles(const std::vector<CountedTriangle>& records) {
  std::vector<Triangle> t;
  for (const CountedTriangle& r : records)
    t.push_back({glm::dvec3(r.corners[0]), glm::dvec3(r.corners[1]), glm::dvec3(r.corners[2])});
  return t;
}

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

  std::pair<int, double> line(const glm::dvec3& p) {
    if (!directional && p == light) return {-1, 0.0};
    const glm::dvec3 key = directional ? p - glm::dot(p, travel) * travel : glm::normalize(p - light);
    const double along = directional ? glm::dot(p, travel) : glm::length(p - light);
    const std::array<long long, 3> cell = {std::llround(key.x / tolerance), std::llround(key.y / tolerance),
                                           std::llround(key.z / tolerance)};
    for (long long dz = -1; dz <= 1; ++dz)
      for (long long dy = -1; dy <= 1; ++dy)
        for (long long dx = -1; dx <= 1; ++dx) {
          const auto it = cells.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (it != cells.end()) return {it->second, along};
        }
    cells.emplace(cell, count);
    return {count++, along};
  }
};

// Corners welded by their exact bits; each undirected edge must appear once in
// each direction, unless both its ends lie on one line from the light: there
// the edges, as signed stretches of the line, must cancel.
Closure closure(const std::vector<CountedTriangle>& records, Lines lines) {
  std::unordered_map<std::string, uint32_t> ids;
  auto id = [&](const glm::vec4& p) {
    std::string key(12, '\0');
    std::memcpy(key.data(), &p, 12);
    return ids.emplace(key, static_cast<uint32_t>(ids.size())).first->second;
  };
  std::unordered_map<uint64_t, int> half_edges;
  std::map<int, std::vector<std::pair<double, double>>> stretches;  // per line: (from, to) along it
  Closure c;
  for (const CountedTriangle& r : records) {
    const uint32_t v[3] = {id(r.corners[0]), id(r.corners[1]), id(r.corners[2])};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      ++c.degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const auto [la, a] = lines.line(glm::dvec3(r.corners[k]));
      const auto [lb, b] = lines.line(glm::dvec3(r.corners[(k + 1) % 3]));
      if (la == lb || la < 0 || lb < 0) stretches[std::max(la, lb)].push_back({a, b});
      else ++half_edges[(uint64_t(v[k]) << 32) | v[(k + 1) % 3]];
    }
  }
  for (const auto& [line, along] : stretches) {
    std::vector<double> ends;
    for (const auto& [a, b] : along) ends.insert(ends.end(), {a, b});
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    std::vector<int> change(ends.size() + 1, 0);
    for (const auto& [a, b] : along) {
      const auto at = [&](double x) { return std::lower_bound(ends.begin(), ends.end(), x) - ends.begin(); };
      ++change[static_cast<size_t>(at(a))];
      --change[static_cast<size_t>(at(b))];
    }
    int covered = 0;
    for (const int step : change) c.uncancelled_stretches += (covered += step) != 0;
  }
  for (const auto& [key, count] : half_edges) {
    const uint64_t reverse = (key << 32) | (key >> 32);
    const auto it = half_edges.find(reverse);
    const int back = it == half_edges.end() ? 0 : it->second;
    if (count == 1 && back == 1) continue;
    if (count + back == 1) ++c.boundary;
    else if (back == 0) ++c.inconsistent;
    else ++c.other;
  }
  c.vertices = ids.size();
  return c;
}

// Lines for a light: 10⁻⁵ rad between directions, 10⁻⁴ m between a
// directional light's lines (the grids' spacings are above 10⁻³ rad and 0.1 m,
// float's rounding of these coordinates below 10⁻⁶).
Lines lines_of(const Light& light) {
  const bool directional = light.type == LightType::directional;
  return {glm::dvec3(light.position), glm::normalize(glm::dvec3(light.direction)), directional, directional ? 1e-4 : 1e-5,
          {}, 0};
}

double signed_volume(const std::vector<Triangle>& mesh, const glm::dvec3& origin) {
  double v = 0.0;
  for (const Triangle& t : mesh) v += glm::dot(t.a - origin, glm::cross(t.b - origin, t.c - origin));
  return v / 6.0;
}

// Crossings of the ray x + t·dir (t > 0) with the mesh (Möller–Trumbore, double): odd = inside.
bool inside(const std::vector<Triangle>& mesh, const glm::dvec3& x, const glm::dvec3& dir) {
  int crossings = 0;
  for (const Triangle& t : mesh) {
    const glm::dvec3 e1 = t.b - t.a, e2 = t.c - t.a, p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) continue;
    const glm::dvec3 s = x - t.a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    if (glm::dot(e2, q) / det > 0.0) ++crossings;
  }
  return crossings % 2 == 1;
}

glm::dvec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
}

// Parity from two random rays; -1 when they disagree (x within rounding of the surface).
int parity(const std::vector<Triangle>& mesh, const glm::dvec3& x, std::mt19937& rng) {
  const bool a = inside(mesh, x, random_direction(rng)), b = inside(mesh, x, random_direction(rng));
  return a == b ? (a ? 1 : 0) : -1;
}

std::unique_ptr<LightVolumeMesh> built(Rig& rig, int resolution, Depth depth) {
  auto mesh = std::make_unique<LightVolumeMesh>(resolution, depth);
  mesh->prepare();
  mesh->build(rig.frame);
  return mesh;
}

// A record as lit_intervals.glsl reads it: light 0, weight 1, a unit normal,
// or, for a triangle with no area, no normal (no ray crosses it:
// crossings.frag.glsl's t is not finite).
bool well_formed(const CountedTriangle& t) {
  const glm::vec3 n(t.plane), a(t.corners[0]), b(t.corners[1]), c(t.corners[2]);
  if (t.light_weight != glm::ivec4(0, 1, 0, 0)) return false;
  if (n == glm::vec3(0.0f)) return a == b || b == c || c == a;
  return std::abs(glm::length(n) - 1.0f) < 1e-5f;
}

// ---- 1. closed, and 2. outward by volume ---------------------------------------------------

struct Case {
  Kind kind;
  int size;
};

// gtest prints a parameter it cannot print as a byte dump in ctest's listing.
void PrintTo(const Case& c, std::ostream* os) { *os << name(c.kind) << " map " << c.size << "²"; }

class LightVolume : public ::testing::TestWithParam<Case> {};

TEST_P(LightVolume, ClosedAndOutwardAtEveryResolutionAndDepth) {
  gpu::Context& context = gpu::Context::headless();
  const Case c = GetParam();
  Rig rig(c.kind, c.size, 7);
  rig.render(rig.eye());
  for (const int r : {32, 64, c.size})
    for (const Depth depth : {Depth::texel, Depth::shell}) {
      auto mesh = built(rig, r, depth);
      const std::vector<CountedTriangle> records = mesh->read_back();
      const bool shell = depth == Depth::shell;
      const GLsizei expected = c.kind == Kind::spot    ? (shell ? 4 * r * r + 8 * r : 6 * r * r + 12 * r)
                               : c.kind == Kind::point ? (shell ? 24 * r * r : 36 * r * r + 48 * r)
                                                       : (shell ? 4 * r * r + 8 * r : 6 * r * r + 20 * r + 14);
      ASSERT_EQ(mesh->triangle_count(), expected);
      ASSERT_EQ(records.size(), static_cast<size_t>(expected));
      const Closure closed = closure(records, lines_of(rig.light()));
      const double volume = signed_volume(triangles(records), glm::dvec3(rig.light().position));
      std::printf("%s S=%d R=%d depth=%d: %zu triangles, %zu vertices; boundary edges %zu, inconsistently wound %zu, "
                  "other %zu, uncancelled stretches %zu, degenerate %zu; volume %.6g\n",
                  name(c.kind), c.size, r, static_cast<int>(depth), records.size(), closed.vertices, closed.boundary,
                  closed.inconsistent, closed.other, closed.uncancelled_stretches, closed.degenerate, volume);
      EXPECT_EQ(closed.boundary, 0u);
      EXPECT_EQ(closed.inconsistent, 0u);
      EXPECT_EQ(closed.other, 0u);
      EXPECT_EQ(closed.uncancelled_stretches, 0u);
      // The texel mesh's walls between cells of one depth, and where its
      // border's sides need no step, are records with no area: no crossing.
      if (shell) {
        EXPECT_EQ(closed.degenerate, 0u);
      }
      EXPECT_GT(volume, 0.0);
      // plane.w = n·a, from the corner the plane was taken at (write_triangle: opposite the longest edge).
      for (size_t k = 0; k < records.size(); k += 97) {
        const CountedTriangle& t = records[k];
        ASSERT_TRUE(well_formed(t)) << k;
        ASSERT_NEAR(t.plane.w, glm::dot(glm::vec3(t.plane), glm::vec3(t.corners[0])),
                    1e-5f * (1.0f + glm::length(glm::vec3(t.corners[0]))));
      }
    }
  context.check("light volume closure");
}

INSTANTIATE_TEST_SUITE_P(Kinds, LightVolume,
                         ::testing::Values(Case{Kind::spot, 128}, Case{Kind::point, 96}, Case{Kind::directional, 128}),
                         [](const auto& info) { return std::string(name(info.param.kind)); });

// ---- 2. inside and outside by parity -------------------------------------------------------

// Points whose distance lies below every lit depth (Rig::texel) of the 3×3
// texels around theirs (by 0.1%: the flat triangles' chord) are inside, above every one
// outside; points between are left out — which includes every point within a
// texel of a discontinuity that lies between its two sides. The rest must agree
// with the read-back mesh's parity (texel depths at R = S).
struct Tally {
  int inside = 0, outside = 0, skipped = 0, ambiguous = 0, wrong = 0;
};

void expect(Tally& tally, int expected, int found) {
  if (expected < 0) {
    ++tally.skipped;
    return;
  }
  if (found < 0) {
    ++tally.ambiguous;
    return;
  }
  (expected ? tally.inside : tally.outside)++;
  if (expected != found) ++tally.wrong;
}

// The 3×3 texels around (a, b) of one face or map: lowest and highest lit depth.
std::pair<double, double> neighbourhood(const Rig& rig, int face, int a, int b) {
  double lo = INFINITY, hi = -INFINITY;
  for (int j = std::max(b - 1, 0); j <= std::min(b + 1, rig.size - 1); ++j)
    for (int i = std::max(a - 1, 0); i <= std::min(a + 1, rig.size - 1); ++i) {
      lo = std::min(lo, rig.texel(face, i, j));
      hi = std::max(hi, rig.texel(face, i, j));
    }
  return {lo, hi};
}

int classify(double d, std::pair<double, double> range, double margin) {
  if (d < range.first - margin) return 1;
  if (d > range.second + margin) return 0;
  return -1;
}

TEST_P(LightVolume, PointsInsideAndOutsideTheStoredSurfaceAgreeWithParity) {
  gpu::Context& context = gpu::Context::headless();
  const Case c = GetParam();
  const int size = c.kind == Kind::point ? 48 : 96;  // R = S: the parity rays cross every triangle
  Rig rig(c.kind, size, 11);
  rig.render(rig.eye());
  auto mesh = built(rig, size, Depth::texel);
  const std::vector<Triangle> t = triangles(mesh->read_back());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Tally tally;
  const glm::dvec3 l(rig.light().position);
  for (int n = 0; n < 1500; ++n) {
    if (c.kind == Kind::point) {
      const glm::dvec3 dir = random_direction(rng), a = glm::abs(dir);
      // The face and (s, t) as GL selects them (light_volume_mesh.comp.glsl's eye pass).
      int face;
      glm::dvec2 st;
      if (a.x >= a.y && a.x >= a.z) {
        face = dir.x >= 0 ? 0 : 1;
        st = glm::dvec2(dir.x >= 0 ? -dir.z : dir.z, -dir.y) / a.x;
      } else if (a.y >= a.z) {
        face = dir.y >= 0 ? 2 : 3;
        st = glm::dvec2(dir.x, dir.y >= 0 ? dir.z : -dir.z) / a.y;
      } else {
        face = dir.z >= 0 ? 4 : 5;
        st = glm::dvec2(dir.z >= 0 ? dir.x : -dir.x, -dir.y) / a.z;
      }
      const int i = std::min(int((st.x + 1) / 2 * size), size - 1), j = std::min(int((st.y + 1) / 2 * size), size - 1);
      if (i == 0 || j == 0 || i == size - 1 || j == size - 1) continue;  // the 3×3 would cross a seam
      const auto range = neighbourhood(rig, face, i, j);
      const double d = 1.25 * range.second * u(rng);
      expect(tally, classify(d, range, 1e-3 * range.second), parity(t, l + d * dir, rng));
      continue;
    }
    // 2D maps: NDC a little beyond the map (outside the spot's frustum; the sun's skirt).
    const double x = -1.2 + 2.4 * u(rng), y = -1.2 + 2.4 * u(rng);
    const bool in_map = std::abs(x) < 1.0 && std::abs(y) < 1.0;
    if (c.kind == Kind::spot) {
      if (!in_map) {
        const double d = 20.0 * u(rng);
        expect(tally, std::abs(x) > 1.001 || std::abs(y) > 1.001 ? 0 : -1, parity(t, rig.point_2d(x, y, d), rng));
        continue;
      }
      const int i = std::min(int((x + 1) / 2 * size), size - 1), j = std::min(int((y + 1) / 2 * size), size - 1);
      const auto range = neighbourhood(rig, 0, i, j);
      const double d = 1.25 * std::min(range.second, 30.0) * u(rng);
      expect(tally, classify(d, range, 1e-3 * range.second), parity(t, rig.point_2d(x, y, d), rng));
    } else {
      // Depths along the light's travel, from before the cap to past the skirt.
      const double cap = rig.cap_depth(), far = rig.far_depth();
      if (!in_map) {
        const double d = cap - 5.0 + (far - cap + 10.0) * u(rng);
        const int expected = d > cap + 1e-3 && d < far - 1e-3 ? 1 : d < cap - 1e-3 || d > far + 2.0 ? 0 : -1;
        expect(tally, std::abs(x) > 1.001 || std::abs(y) > 1.001 ? expected : -1, parity(t, rig.point_2d(x, y, d), rng));
        continue;
      }
      const int i = std::min(int((x + 1) / 2 * size), size - 1), j = std::min(int((y + 1) / 2 * size), size - 1);
      const auto range = neighbourhood(rig, 0, i, j);
      const double d = range.first - 10.0 + (std::min(range.second, 40.0) - range.first + 20.0) * u(rng);
      const int expected = d < cap + 1e-3 ? -1 : classify(d, range, 1e-3 * std::abs(range.second));
      expect(tally, expected, parity(t, rig.point_2d(x, y, d), rng));
    }
  }
  std::printf("%s S=R=%d texel: %zu triangles; %d points inside and %d outside agree but %d; %d left out (between the "
              "3x3 texels' depths, or a cube face's border ring), %d within rounding of the surface\n",
              name(c.kind), size, t.size(), tally.inside, tally.outside, tally.wrong, tally.skipped, tally.ambiguous);
  EXPECT_EQ(tally.wrong, 0);
  EXPECT_GT(tally.inside, 200);
  EXPECT_GT(tally.outside, 200);
  context.check("light volume parity");
}

// ---- 3. eye counts -------------------------------------------------------------------------

TEST_P(LightVolume, EyeCountsAreZeroInsideOneOutsideAndTheMeshsParity) {
  gpu::Context& context = gpu::Context::headless();
  const Case c = GetParam();
  const int size = 64;
  Rig rig(c.kind, size, 13);
  const glm::dvec3 l(rig.light().position);
  rig.render(rig.eye());
  // Known eyes: near the light (inside), behind a spot or beside its frustum,
  // far outside the sun's map (its skirt: inside), and just above and below a
  // texel whose 3×3 neighbourhood holds occluders.
  std::vector<std::pair<glm::dvec3, int>> known;
  if (c.kind == Kind::spot)
    known = {{l + glm::dvec3(0.1, -1.0, 0.2), 0}, {l + glm::dvec3(0, 1, 0), 1}, {l + glm::dvec3(8, -1, 0), 1}};
  else if (c.kind == Kind::point)
    known = {{l + glm::dvec3(0.1, 0.2, -0.3), 0}, {l + glm::dvec3(0.3, -0.5, 0.2), 0}};
  else
    known = {{glm::dvec3(60, 5, 0), 0}, {glm::dvec3(-3, 8, 70), 0}};
  for (int k = 0; k < 3; ++k) {
    const int i = size / 2 + 7 * k - 7, j = size / 2 - 5 * k + 3;
    const int face = c.kind == Kind::point ? 4 : 0;
    bool finite = true;
    for (int b = j - 1; b <= j + 1; ++b)
      for (int a = i - 1; a <= i + 1; ++a)
        finite = finite && rig.stored[(static_cast<size_t>(face) * size + b) * size + a] < 1e30f;
    const auto range = neighbourhood(rig, face, i, j);
    if (!finite || range.second > 1e3) continue;
    const double x = 2.0 * (i + 0.5) / size - 1.0, y = 2.0 * (j + 0.5) / size - 1.0;
    auto at = [&](double d) {
      if (c.kind != Kind::point) return rig.point_2d(x, y, d);
      return l + d * glm::normalize(glm::dvec3(x, -y, 1.0));  // face +z: (s, −t, 1)
    };
    const double above = c.kind == Kind::directional ? range.first - 1.0 : 0.5 * range.first;
    known.push_back({at(above), 0});
    known.push_back({at(range.second + 1.0), 1});
  }
  ASSERT_GE(known.size(), 6u);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int n = 0; n < 24; ++n) known.push_back({l + glm::dvec3(8 * u(rng), 10 * u(rng) - 4, 8 * u(rng)), -1});
  // The shell's count (0: inside the shell) is checked by parity alone (its
  // vertices gather cells wider than the known eyes' 3×3 texels).
  for (const Depth depth : {Depth::texel, Depth::shell}) {
    int agree = 0, ambiguous = 0, in_shell = 0;
    for (const auto& [eye, expected] : known) {
      rig.render(glm::vec3(eye));
      auto mesh = built(rig, 32, depth);
      const std::vector<int> counts = mesh->eye_counts();
      ASSERT_EQ(counts.size(), 1u);
      const int by_parity = parity(triangles(mesh->read_back()), glm::dvec3(glm::vec3(eye)), rng);
      if (expected >= 0 && depth == Depth::texel) {
        EXPECT_EQ(counts[0], expected) << "eye " << eye.x << " " << eye.y << " " << eye.z;
      }
      if (by_parity < 0) {
        ++ambiguous;
        continue;
      }
      EXPECT_EQ(counts[0], by_parity ? 0 : 1) << "eye " << eye.x << " " << eye.y << " " << eye.z;
      agree += counts[0] == (by_parity ? 0 : 1);
      in_shell += depth == Depth::shell && by_parity;
    }
    std::printf("%s, %s mesh: eye counts agree with the read-back mesh's parity at %d of %zu eyes (%d on the "
                "surface, %d inside the shell)\n",
                name(c.kind), depth == Depth::shell ? "shell" : "texel", agree, known.size(), ambiguous, in_shell);
  }
  context.check("light volume eye counts");
}

// ---- 4. the shell around the texel mesh -----------------------------------------------------

// Records per cell: the texel mesh's top at 6k, the shell's inner two at 4k
// and outer two at 4k + 2, each with the cell's first grid vertex as its
// first corner (write_oriented keeps it). The texel mesh's top sits at its
// texel's stored depth, the shell's outer surface a texel past the farthest
// of its cells (a directional map's with no chord), and where the map says
// "no occluder" the inner and the texel's are the far depth, at one
// depth that each computes its own way (origin + depth·step against
// map_point): equal within a few float ulps of coordinates up to 100 m (10⁻⁴ m).
TEST_P(LightVolume, ShellInnerTexelOuterAreOrderedAtEveryCell) {
  gpu::Context& context = gpu::Context::headless();
  const Case c = GetParam();
  Rig rig(c.kind, c.size, 17);
  rig.render(rig.eye());
  const glm::dvec3 l(rig.light().position), d = rig.direction();
  auto depth = [&](const glm::vec4& p) {
    return c.kind == Kind::directional ? glm::dot(glm::dvec3(p), d) : glm::length(glm::dvec3(p) - l);
  };
  for (const int r : {32, 64, c.size}) {
    const std::vector<CountedTriangle> texel = built(rig, r, Depth::texel)->read_back();
    const std::vector<CountedTriangle> shell = built(rig, r, Depth::shell)->read_back();
    const size_t cells = static_cast<size_t>(r) * r * (c.kind == Kind::point ? 6 : 1);
    size_t strict = 0, wrong = 0;
    for (size_t k = 0; k < cells; ++k) {
      const double inner = depth(shell[4 * k].corners[0]), middle = depth(texel[6 * k].corners[0]),
                   outer = depth(shell[4 * k + 2].corners[0]);
      strict += inner < outer;
      wrong += !(inner <= middle + 1e-4 && middle <= outer + 1e-4);
    }
    std::printf("%s S=%d R=%d: %zu cells, inner <= texel <= outer broken at %zu, inner < outer at %zu\n",
                name(c.kind), c.size, r, cells, wrong, strict);
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(strict, cells / 20);
  }
  context.check("light volume shell");
}

// A vertex's depth as the header defines it, computed here from the imported
// map: texel = the lit depth (Rig::texel) of the texel under cell (i, j)'s
// centre, ⌊(2i + 1)·S/(2R)⌋; the shell's inner and outer = the extremes of
// the texels of the cells around the vertex, the outer moved on by a texel
// and the chord (at most 3%: one texel is k/S = 1.1% of the distance for this
// 70° map at S = 128, the chord across a 32² cell's diagonal 0.2%). R
// dividing S, not dividing it,
// and cells of 65² texels, which the shader reduces in 64² sub-blocks
// (CELL_SPLIT, atomics). Grid vertex (i, j) is the first corner of cell (i, j)'s
// first triangle (texel: its top at the cell's depth).
TEST(LightVolumeDepths, VertexDepthsAreTheirTexelOrTheExtremesOfTheirCells) {
  gpu::Context& context = gpu::Context::headless();
  for (const auto& [size, r] : {std::pair{128, 32}, std::pair{128, 48}, std::pair{2048, 32}}) {
    Rig rig(Kind::spot, size, 29);
    rig.render(rig.eye());
    const glm::dvec3 l(rig.light().position);
    for (const bool shell : {false, true}) {
      const std::vector<CountedTriangle> records = built(rig, r, shell ? Depth::shell : Depth::texel)->read_back();
      double worst = 0.0, outer_low = INFINITY, outer_high = 0.0;
      for (int j = 0; j < r; ++j)
        for (int i = 0; i < r; ++i) {
          double low = INFINITY, high = -INFINITY;
          for (int cj = std::max(j - 1, 0); cj <= j; ++cj)
            for (int ci = std::max(i - 1, 0); ci <= i; ++ci)
              for (int y = cj * size / r; y < ((cj + 1) * size + r - 1) / r; ++y)
                for (int x = ci * size / r; x < ((ci + 1) * size + r - 1) / r; ++x) {
                  low = std::min(low, rig.texel(0, x, y));
                  high = std::max(high, rig.texel(0, x, y));
                }
          const size_t cell = static_cast<size_t>(j) * r + i;
          auto distance = [&](size_t record) { return glm::length(glm::dvec3(records[record].corners[0]) - l); };
          const double expected = shell ? low : rig.texel(0, (2 * i + 1) * size / (2 * r), (2 * j + 1) * size / (2 * r));
          const double found = distance(shell ? 4 * cell : 6 * cell);
          worst = std::max(worst, std::abs(found - expected) / expected);
          if (shell) {
            const double outer = distance(4 * cell + 2) / high - 1.0;
            outer_low = std::min(outer_low, outer);
            outer_high = std::max(outer_high, outer);
          }
        }
      std::printf("spot S=%d R=%d %s: vertex distances against their texel or their cells' minimum: worst relative "
                  "error %.2g",
                  size, r, shell ? "shell" : "texel", worst);
      if (shell) std::printf("; outer over the cells' maximum: %.4f to %.4f", outer_low, outer_high);
      std::printf("\n");
      EXPECT_LT(worst, 1e-5);
      if (shell) {
        EXPECT_GT(outer_low, 0.0);
        EXPECT_LT(outer_high, 0.03);
      }
    }
  }
  context.check("light volume extremes");
}

// ---- airlight's own maps ----------------------------------------------------------------------

// three_lights with the frame's own maps (a cube for the point light, a
// perspective map for the spot, airlight's orthographic fit for the sun):
// each light's range of the buffer is closed and outward, and its eye count is
// its mesh's parity, from the scene's camera and from inside each light's volume.
TEST(LightVolumeOwnMaps, ThreeLightsClosedOutwardAndEyeCountsAgree) {
  gpu::Context& context = gpu::Context::headless();
  Scene scene = builtin_scene("three_lights");
  SceneFrame frame;
  frame.prepare(scene);
  LightVolumeMesh mesh(64, Depth::texel);
  mesh.prepare();
  std::mt19937 rng(23);
  std::vector<glm::vec3> eyes = {scene.camera.position};
  for (const Light& light : scene.lights)
    if (light.type != LightType::directional) eyes.push_back(light.position + 0.3f * glm::normalize(light.direction));
  for (const glm::vec3& eye : eyes) {
    scene.camera.position = eye;
    PassTimer timer;
    frame.render(frame_inputs(scene, 32, 24), FrameSettings{256, 1.0f}, nullptr, {true, false}, timer);
    mesh.build(frame);
    const std::vector<CountedTriangle> all = mesh.read_back();
    const std::vector<int> counts = mesh.eye_counts();
    ASSERT_EQ(mesh.light_ranges().size(), scene.lights.size());
    for (size_t i = 0; i < scene.lights.size(); ++i) {
      const auto& range = mesh.light_ranges()[i];
      ASSERT_NE(range.kind, LightVolumeMesh::Kind::none);
      const std::vector<CountedTriangle> own(all.begin() + range.first, all.begin() + range.first + range.count);
      for (const CountedTriangle& t : own) ASSERT_EQ(t.light_weight.x, static_cast<int>(i));
      const Closure closed = closure(own, lines_of(scene.lights[i]));
      const std::vector<Triangle> t = triangles(own);
      const double volume = signed_volume(t, glm::dvec3(eye));
      const int by_parity = parity(t, glm::dvec3(eye), rng);
      std::printf("three_lights light %zu (kind %d), eye (%.1f %.1f %.1f): %zu triangles, boundary %zu, inconsistent %zu, "
                  "volume %.4g, eye count %d, parity %d\n",
                  i, static_cast<int>(range.kind), eye.x, eye.y, eye.z, own.size(), closed.boundary,
                  closed.inconsistent, volume, counts[i], by_parity);
      EXPECT_EQ(closed.boundary + closed.inconsistent + closed.other + closed.uncancelled_stretches, 0u);
      EXPECT_GT(volume, 0.0);
      if (by_parity >= 0) {
        EXPECT_EQ(counts[i], by_parity ? 0 : 1);
      }
    }
  }
  context.check("light volume own maps");
}

// ---- the contract with LitIntervalPass ------------------------------------------------------

// The mesh (texel depths, R = S) and its eye counts handed to LitIntervalPass:
// Γ over the stretches where each light's count is 0 gives raymarch's image
// from the same maps (up to the march's error and a texel's worth of shadow
// edges), from the scene's camera and from a camera inside a light's volume.
TEST(LightVolumeAirlight, CountingTheMeshGivesRaymarchsImage) {
  gpu::Context& context = gpu::Context::headless();
  constexpr int w = 48, h = 36, s = 128;
  for (const char* name : {"teapot_spot", "three_lights"}) {
    Scene scene = builtin_scene(name);
    for (const bool moved : {false, true}) {
      if (moved) scene.camera.position = scene.lights[0].position + 0.5f * glm::normalize(scene.lights[0].direction);
      const Image marched = test::render(find_method("raymarch"), scene,
                                         {"steps=256", "shadow_resolution=" + std::to_string(s)}, w, h).airlight;
      SceneFrame frame;
      frame.prepare(scene);
      PassTimer timer;
      frame.render(frame_inputs(scene, w, h), FrameSettings{s, 1.0f}, nullptr, {true, false}, timer);
      LightVolumeMesh mesh(s, Depth::texel);
      mesh.prepare();
      mesh.build(frame);
      LitIntervalPass pass{Settings(lit_interval_settings())};
      pass.prepare();
      const gpu::Texture target = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, w, h);
      pass.run(frame, mesh.read_back(), {mesh.eye_counts(), {}}, target, timer);
      const Image counted = gpu::read_image(target, w, h);
      const ImageError e = compare_images(counted, marched);
      std::string counts;
      for (const int c : mesh.eye_counts()) counts += std::to_string(c);
      std::printf("%s%s: %d triangles, eye counts %s; counted against raymarch (N = 256): rRMSE %.4f, max abs %.4g "
                  "(mean %.4g)\n",
                  name, moved ? " (camera in light 0's volume)" : "", mesh.triangle_count(), counts.c_str(), e.rel_rmse,
                  e.max_abs, e.mean_reference);
      EXPECT_LT(e.rel_rmse, 0.05);
    }
  }
  context.check("light volume airlight");
}

// ---- build time ------------------------------------------------------------------------------

// A 1024² grid over a spot's 1024² map is 2.1 M records, more than one storage
// binding holds on llvmpipe (1.68 M): the build writes them through several
// bound ranges, and every record must come out written (the build's time is
// the benchmark's business, docs/decisions.md).
TEST(LightVolumeRanges, EveryRecordWrittenBeyondOneBinding) {
  gpu::Context& context = gpu::Context::headless();
  Rig rig(Kind::spot, 1024, 19);
  rig.render(rig.eye());
  LightVolumeMesh mesh(1024, Depth::texel);
  mesh.prepare();
  mesh.build(rig.frame);
  const std::vector<CountedTriangle> records = mesh.read_back();
  size_t written = 0;
  for (const CountedTriangle& t : records) written += well_formed(t);
  std::printf("%zu records, %zu written (%d per binding)\n", records.size(), written, mesh.max_records_per_binding());
  EXPECT_GT(records.size(), static_cast<size_t>(mesh.max_records_per_binding()));
  EXPECT_EQ(written, records.size());
  context.check("light volume ranges");
}

}  // namespace
}  // namespace airlight::kit
