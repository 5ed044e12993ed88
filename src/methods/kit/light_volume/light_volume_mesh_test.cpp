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
#include "methods/kit/light_volume/light_volume_mesh_test_support.hpp"

#include "core/metrics.hpp"
#include "gpu/context.hpp"
#include "gpu/gl.hpp"
#include "gpu/program.hpp"
#include "methods/kit/counting/lit_interval_pass.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <airlight/method.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace airlight::kit {
namespace {

using namespace volume_test;

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
      // The face and (s, t) as GL selects them (eye_count.comp.glsl).
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
      const std::vector<int> counts = mesh->eye_counts().counts;
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
  mesh.prepare(scene);
  std::mt19937 rng(23);
  std::vector<glm::vec3> eyes = {scene.camera.position};
  for (const Light& light : scene.lights)
    if (light.type != LightType::directional) eyes.push_back(light.position + 0.3f * glm::normalize(light.direction));
  for (const glm::vec3& eye : eyes) {
    scene.camera.position = eye;
    PassTimer timer;
    frame.render(frame_inputs(scene, 32, 24), FrameSettings{256, 1.0f}, nullptr, {true, false}, timer);
    mesh.build(frame, timer);
    const std::vector<CountedTriangle> all = mesh.read_back();
    const std::vector<int> counts = mesh.eye_counts().counts;
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
      mesh.prepare(scene);
      mesh.build(frame, timer);
      LitIntervalPass pass{Settings(lit_interval_settings()), mesh.has_eye_planes()};
      pass.prepare();
      const gpu::Texture target = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, w, h);
      pass.run(frame, mesh, target, timer);
      const Image counted = gpu::read_image(target, w, h);
      const ImageError e = compare_images(counted, marched);
      std::string counts;
      for (const int c : mesh.eye_counts().counts) counts += std::to_string(c);
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
  mesh.prepare(rig.scene);
  PassTimer timer;
  mesh.build(rig.frame, timer);
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
