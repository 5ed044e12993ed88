#include "geometry/shadow_edges.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <map>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace airlight::geometry {
namespace {

// A mesh as a caster receives it: positions and index triples.
struct TestMesh {
  explicit TestMesh(std::string name, bool closed = false) : name(std::move(name)), closed(closed) {}
  std::string name;
  bool closed;  // what its builder means it to be
  std::vector<glm::vec3> positions;
  std::vector<glm::uvec3> triangles;

  uint32_t vertex(const glm::dvec3& p) {
    positions.emplace_back(p);
    return static_cast<uint32_t>(positions.size() - 1);
  }
  void triangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const uint32_t i = vertex(a), j = vertex(b), k = vertex(c);
    triangles.emplace_back(i, j, k);
  }
  void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    triangles.emplace_back(a, b, c);
    triangles.emplace_back(a, c, d);
  }
};

void split(TestMesh& mesh, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, int levels) {
  if (levels == 0) return mesh.triangle(a, b, c);
  // a + b = b + a exactly, so both triangles beside an edge get the same midpoint.
  const glm::dvec3 ab = glm::normalize(a + b), bc = glm::normalize(b + c), ca = glm::normalize(c + a);
  split(mesh, a, ab, ca, levels - 1);
  split(mesh, ab, b, bc, levels - 1);
  split(mesh, ca, bc, c, levels - 1);
  split(mesh, ab, bc, ca, levels - 1);
}

// An icosahedron's faces split `levels` times onto the unit sphere, every triangle with its
// own three vertices: welding must join them all.
TestMesh icosphere(int levels) {
  const double t = std::numbers::phi;
  const std::array<glm::dvec3, 12> v = {{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                         {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                         {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}}};
  constexpr int faces[20][3] = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  TestMesh mesh{"icosphere", true};
  for (const auto& f : faces)
    split(mesh, glm::normalize(v[f[0]]), glm::normalize(v[f[1]]), glm::normalize(v[f[2]]), levels);
  return mesh;
}

// A UV sphere as texture-mapped meshes make it: a seam column (j = segments repeats j = 0)
// and a pole vertex per column, so welding joins the seam and the poles and collapses one
// triangle of each polar quad. `bands` of its segments/2 latitude bands from the top: all of
// them, or half for a half sphere open at the equator.
TestMesh uv_sphere(int segments, int bands, std::string name) {
  const int rows = segments / 2;
  TestMesh mesh{std::move(name), bands == rows};
  for (int k = 0; k <= bands; ++k)
    for (int j = 0; j <= segments; ++j) {
      const double theta = std::numbers::pi * k / rows;
      const double phi = 2.0 * std::numbers::pi * (j % segments) / segments;
      const bool pole = k == 0 || k == rows;  // exactly on the axis, where sin θ would not be 0
      const double s = pole ? 0.0 : std::sin(theta), y = pole ? (k == 0 ? 1.0 : -1.0) : std::cos(theta);
      mesh.vertex({s * std::cos(phi), y, -s * std::sin(phi)});
    }
  const auto at = [&](int k, int j) { return static_cast<uint32_t>(k * (segments + 1) + j); };
  for (int k = 0; k < bands; ++k)
    for (int j = 0; j < segments; ++j) mesh.quad(at(k, j), at(k + 1, j), at(k + 1, j + 1), at(k, j + 1));
  return mesh;
}

// An axis-aligned box with flat faces, each with its own four vertices (as for flat normals).
void add_box(TestMesh& mesh, const glm::dvec3& lo, const glm::dvec3& hi) {
  // Corner c has x from bit 0, y from bit 1, z from bit 2; faces wound outward.
  constexpr int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                               {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& face : faces) {
    uint32_t i[4];
    for (int k = 0; k < 4; ++k) {
      const int c = face[k];
      i[k] = mesh.vertex({c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z});
    }
    mesh.quad(i[0], i[1], i[2], i[3]);
  }
}

TestMesh box() {
  TestMesh mesh{"box", true};
  add_box(mesh, {-0.8, -0.5, -0.6}, {0.7, 0.9, 0.5});
  return mesh;
}

// Two closed boxes through each other in one mesh: a self-intersecting union.
TestMesh two_boxes() {
  TestMesh mesh{"two boxes", true};
  add_box(mesh, {-1.0, -0.6, -0.6}, {0.4, 0.6, 0.6});
  add_box(mesh, {-0.2, -0.9, -0.3}, {1.0, 0.3, 0.9});
  return mesh;
}

TestMesh torus(int around, int tube) {
  TestMesh mesh{"torus", true};
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) {
      const double u = 2.0 * std::numbers::pi * i / around, v = 2.0 * std::numbers::pi * j / tube;
      const double r = 1.0 + 0.35 * std::cos(v);
      mesh.vertex({r * std::cos(u), 0.35 * std::sin(v), r * std::sin(u)});
    }
  const auto at = [&](int i, int j) { return static_cast<uint32_t>((i % around) * tube + j % tube); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < tube; ++j) mesh.quad(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  return mesh;
}

TestMesh open_quad() {
  TestMesh mesh{"quad"};
  mesh.quad(mesh.vertex({-1, 0, -1}), mesh.vertex({1, 0, -1}), mesh.vertex({1, 0.3, 1}),
            mesh.vertex({-1, 0, 1}));
  return mesh;
}

// Random triangles through one another, three coplanar overlapping ones, three on one edge
// (non-manifold, one of them reversed) and one with collinear vertices.
TestMesh soup(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto any = [&] { return glm::dvec3(u(rng), u(rng), u(rng)); };
  const auto flat = [&] { return glm::dvec3(u(rng), 0.25, u(rng)); };
  TestMesh mesh{"soup"};
  for (int k = 0; k < 12; ++k) mesh.triangle(any(), any(), any());
  for (int k = 0; k < 3; ++k) mesh.triangle(flat(), flat(), flat());
  const uint32_t a = mesh.vertex(any()), b = mesh.vertex(any());
  for (int k = 0; k < 3; ++k) {
    const uint32_t c = mesh.vertex(any());
    mesh.triangles.push_back(k == 0 ? glm::uvec3(b, a, c) : glm::uvec3(a, b, c));
  }
  mesh.triangle({-1, 0.1, 0.2}, {0, 0.1, 0.2}, {1, 0.1, 0.2});
  return mesh;
}

// A triangle whose edge P1–P2 meets two triangles at its midpoint M, which is not its vertex.
TestMesh t_junction() {
  TestMesh mesh{"T-junction"};
  const uint32_t p0 = mesh.vertex({-1, 0, -1}), p1 = mesh.vertex({1, 0, -1}), p2 = mesh.vertex({-1, 0, 1});
  const uint32_t m = mesh.vertex({0, 0, 0}), q = mesh.vertex({1, 0.8, 1});
  mesh.triangles = {{p0, p1, p2}, {p1, q, m}, {m, q, p2}};
  return mesh;
}

std::vector<TestMesh> test_meshes(std::mt19937& rng) {
  return {icosphere(2), uv_sphere(16, 8, "UV sphere"), box(), torus(16, 8), two_boxes(),
          open_quad(), uv_sphere(16, 4, "half sphere"), soup(rng), t_junction()};
}

glm::vec3 random_point(std::mt19937& rng, float half_size) {
  std::uniform_real_distribution<float> u(-half_size, half_size);
  const float x = u(rng), y = u(rng), z = u(rng);
  return {x, y, z};
}

// Three each of point, spot and directional lights, anywhere around the meshes (inside some).
std::vector<LightOrigin> random_lights(std::mt19937& rng) {
  std::vector<LightOrigin> lights;
  for (int k = 0; k < 3; ++k)
    for (const LightType type : {LightType::point, LightType::spot, LightType::directional}) {
      Light light;
      light.type = type;
      light.position = random_point(rng, 3.0f);
      do light.direction = random_point(rng, 1.0f);
      while (glm::length(light.direction) < 0.1f);
      light.direction = glm::normalize(light.direction);
      lights.push_back(light_origin(light));
    }
  return lights;
}

// Pairs closer than this to a plane or an edge are skipped: the double arithmetic here and in
// shadow_count errs by about 1e-14 m at these coordinates (≤ 5 m), so 1e-9 m is far clear of it,
// and random points come that close to one of ~1000 planes about 1e-6 of the time.
constexpr double kEps = 1e-9;

// The part of a plane { O + α·P + β·Q } (normal n = P × Q) where each bound
// g = kα·α + kβ·β + k0 ≥ 0, with `per_unit` the distance from the bound's line per unit of g.
struct Region {
  glm::dvec3 origin, p, q, n;
  struct Bound {
    double k_alpha, k_beta, k0, per_unit;
  };
  std::array<Bound, 3> bounds;
};

// W(a, b) as shadow_edges.hpp writes it, with its n in double.
Region wedge(const glm::vec3& fa, const glm::vec3& fb, const LightOrigin& light) {
  const glm::dvec3 a(fa), b(fb);
  if (light.directional) {
    // a + α·D + β·(b − a): α ≥ 0 (line ab), β ≥ 0 (ray from a), 1 − β ≥ 0 (ray from b).
    const glm::dvec3 d(light.direction), n = glm::cross(d, b - a);
    const double l = glm::length(n);
    return {a, d, b - a, n, {{{1, 0, 0, l / glm::length(b - a)}, {0, 1, 0, l}, {0, -1, 1, l}}}};
  }
  // L + α·(a − L) + β·(b − L): α ≥ 0, β ≥ 0 (the rays through b and a), α + β ≥ 1 (line ab).
  const glm::dvec3 L(light.position), n = glm::cross(a - L, b - L);
  const double l = glm::length(n);
  return {L, a - L, b - L, n,
          {{{1, 0, 0, l / glm::length(b - L)}, {0, 1, 0, l / glm::length(a - L)},
            {1, 1, -1, l / glm::length(b - a)}}}};
}

Region triangle_region(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double l = glm::length(n);
  return {a, b - a, c - a, n,
          {{{1, 0, 0, l / glm::length(c - a)}, {0, 1, 0, l / glm::length(b - a)},
            {-1, -1, 1, l / glm::length(c - b)}}}};
}

enum class Crossing { none, along_n, against_n, too_close };

// Whether the segment e → p crosses the region, found analytically: the point where it meets
// the plane, then that point's α, β against the bounds.
Crossing crossing(const Region& r, const glm::dvec3& e, const glm::dvec3& p) {
  const double l = glm::length(r.n);
  if (l == 0.0) return Crossing::none;  // a line, not a plane: nothing to cross
  const double de = glm::dot(r.n, e - r.origin) / l, dp = glm::dot(r.n, p - r.origin) / l;
  if (std::abs(de) < kEps || std::abs(dp) < kEps) return Crossing::too_close;
  if ((de > 0) == (dp > 0)) return Crossing::none;
  const glm::dvec3 x = e + (p - e) * (de / (de - dp)) - r.origin;
  const double alpha = glm::dot(glm::cross(x, r.q), r.n) / (l * l);
  const double beta = glm::dot(glm::cross(r.p, x), r.n) / (l * l);
  bool inside = true;
  for (const Region::Bound& g : r.bounds) {
    const double value = g.k_alpha * alpha + g.k_beta * beta + g.k0;
    if (std::abs(value) * g.per_unit < kEps) return Crossing::too_close;
    inside = inside && value > 0;
  }
  if (!inside) return Crossing::none;
  return dp > de ? Crossing::along_n : Crossing::against_n;
}

// count(p) − count(e) from what e → p crosses: ±w per plane, and ±1 per triangle (+1 leaving
// the light's side); none when the path or its ends come within kEps of any edge's wedge or
// any triangle, where the counts themselves are too close to call.
std::optional<int> predicted_change(const CasterTopology& caster, const std::vector<ShadowPlane>& planes,
                                    const LightOrigin& light, const glm::dvec3& e, const glm::dvec3& p,
                                    int& triangles_crossed) {
  const std::span<const glm::vec3> world = caster.positions;
  for (const glm::uvec2& edge : caster.edges)
    if (crossing(wedge(world[edge.x], world[edge.y], light), e, p) == Crossing::too_close) return {};
  int change = 0;
  for (const ShadowPlane& plane : planes) {
    const Crossing c = crossing(wedge(plane.a, plane.b, light), e, p);
    if (c != Crossing::none) change += c == Crossing::along_n ? plane.weight : -plane.weight;
  }
  triangles_crossed = 0;
  for (const glm::uvec3& t : caster.triangles) {
    const Region tri =
        triangle_region(glm::dvec3(world[t.x]), glm::dvec3(world[t.y]), glm::dvec3(world[t.z]));
    const Crossing c = crossing(tri, e, p);
    if (c == Crossing::too_close) return {};
    if (c == Crossing::none) continue;
    const double light_side = light.directional ? -glm::dot(tri.n, glm::dvec3(light.direction))
                                                : glm::dot(tri.n, glm::dvec3(light.position) - tri.origin);
    change += (c == Crossing::along_n) == (light_side < 0) ? 1 : -1;
    ++triangles_crossed;
  }
  return change;
}

TEST(ShadowEdges, CountChangesByThePlanesAndTrianglesAPathCrosses) {
  std::mt19937 rng(20250611);
  constexpr int kPairsPerLight = 250;
  std::printf("%-12s %5s %7s %8s %12s %15s %5s\n", "mesh", "pairs", "skipped", "shadowed",
              "cross planes", "cross triangles", "wrong");
  for (const TestMesh& mesh : test_meshes(rng)) {
    const CasterTopology caster = build_topology(mesh.positions, mesh.triangles);
    int pairs = 0, skipped = 0, shadowed = 0, across_planes = 0, across_triangles = 0, wrong = 0;
    for (const LightOrigin& light : random_lights(rng)) {
      std::vector<ShadowPlane> planes;
      append_shadow_planes(caster, caster.positions, light, planes);
      for (int k = 0; k < kPairsPerLight; ++k, ++pairs) {
        const glm::vec3 e = random_point(rng, 2.5f), p = random_point(rng, 2.5f);
        int triangles_crossed = 0;
        const auto change =
            predicted_change(caster, planes, light, glm::dvec3(e), glm::dvec3(p), triangles_crossed);
        if (!change) {
          ++skipped;
          continue;
        }
        const int count_e = shadow_count(caster, caster.positions, light, e);
        const int count_p = shadow_count(caster, caster.positions, light, p);
        shadowed += count_p > 0;
        across_planes += *change != 0 && triangles_crossed == 0;
        across_triangles += triangles_crossed > 0;
        wrong += count_p != count_e + *change;
      }
    }
    std::printf("%-12s %5d %7d %8d %12d %15d %5d\n", mesh.name.c_str(), pairs, skipped, shadowed,
                across_planes, across_triangles, wrong);
    EXPECT_EQ(wrong, 0) << mesh.name;
    EXPECT_GE(pairs - skipped, 2000) << mesh.name;
    // Both terms are exercised: paths whose count changes at planes alone (a view ray's case)
    // and paths through the caster.
    EXPECT_GT(across_planes, 0) << mesh.name;
    EXPECT_GT(across_triangles, 0) << mesh.name;
  }
}

std::vector<std::tuple<float, float, float, float, float, float, int>> sorted(
    const std::vector<ShadowPlane>& planes) {
  std::vector<std::tuple<float, float, float, float, float, float, int>> keys;
  for (const ShadowPlane& s : planes) keys.emplace_back(s.a.x, s.a.y, s.a.z, s.b.x, s.b.y, s.b.z, s.weight);
  std::sort(keys.begin(), keys.end());
  return keys;
}

// The weights are the header's w = Σ_t side_t taken literally: each edge's own n and the
// third vertex c of each triangle on it (shadow_edges.cpp evaluates side_t once per triangle).
TEST(ShadowEdges, WeightsAreTheSidesOfEachEdgesTrianglesSummed) {
  std::mt19937 rng(13);
  for (const TestMesh& mesh : test_meshes(rng)) {
    const CasterTopology caster = build_topology(mesh.positions, mesh.triangles);
    const std::span<const glm::vec3> world = caster.positions;
    for (const LightOrigin& light : random_lights(rng)) {
      std::map<std::pair<uint32_t, uint32_t>, int> literal;
      for (const glm::uvec3& t : caster.triangles)
        for (int k = 0; k < 3; ++k) {
          const uint32_t a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
          const Region w = wedge(world[a], world[b], light);
          const double side = glm::dot(w.n, glm::dvec3(world[t[(k + 2) % 3]]) - w.origin);
          literal[{a, b}] += (side > 0) - (side < 0);
        }
      std::vector<ShadowPlane> expected, planes;
      for (const auto& [edge, w] : literal)
        if (w != 0) expected.push_back({world[edge.first], world[edge.second], w});
      append_shadow_planes(caster, world, light, planes);
      EXPECT_EQ(sorted(planes), sorted(expected)) << mesh.name;
    }
  }
}

TEST(ShadowEdges, WeldingJoinsSeamsAndPolesAndCountsWhatItDrops) {
  std::mt19937 rng(7);
  for (const TestMesh& mesh : test_meshes(rng))
    EXPECT_EQ(build_topology(mesh.positions, mesh.triangles).closed, mesh.closed) << mesh.name;

  const TestMesh ico = icosphere(2);
  const CasterTopology ico_caster = build_topology(ico.positions, ico.triangles);
  EXPECT_EQ(ico.positions.size(), 3u * 320u);
  EXPECT_EQ(ico_caster.positions.size(), 162u);  // 10·4² + 2 vertices of a twice-split icosahedron

  // 16 columns and 8 bands: one pole vertex each and 7 rings of 16 after welding; each polar
  // quad loses the triangle whose two pole corners weld together.
  const TestMesh sphere = uv_sphere(16, 8, "UV sphere");
  const CasterTopology sphere_caster = build_topology(sphere.positions, sphere.triangles);
  EXPECT_EQ(sphere_caster.positions.size(), 2u + 7u * 16u);
  EXPECT_EQ(sphere_caster.collapsed_triangles, 2 * 16);
  EXPECT_EQ(sphere_caster.triangles.size(), 2u * 16u * 8u - 2u * 16u);

  const TestMesh cube = box();
  const CasterTopology cube_caster = build_topology(cube.positions, cube.triangles);
  EXPECT_EQ(cube_caster.positions.size(), 8u);
  ASSERT_EQ(cube_caster.welded_index.size(), 24u);
  for (size_t i = 0; i < 24; ++i) EXPECT_EQ(cube_caster.positions[cube_caster.welded_index[i]], cube.positions[i]);

  const TestMesh mixed = soup(rng);
  const CasterTopology soup_caster = build_topology(mixed.positions, mixed.triangles);
  EXPECT_EQ(soup_caster.zero_area_triangles.size(), 1u);
  EXPECT_EQ(soup_caster.triangles.size(), mixed.triangles.size() - 1);

  // −0 and +0 are one position: a quad split with its diagonal's ends given twice.
  const std::vector<glm::vec3> signed_zeros = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-0.0f, 0, -0.0f}, {1, 1, 0}, {0, 1, 0}};
  const std::vector<glm::uvec3> halves = {{0, 1, 2}, {3, 4, 5}};
  EXPECT_EQ(build_topology(signed_zeros, halves).positions.size(), 4u);
}

TEST(ShadowEdges, RefusesIndicesOutOfRangeAndWorldPositionsThatDoNotMatch) {
  const std::vector<glm::vec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<glm::uvec3> past_the_end = {{0, 1, 3}}, triangle = {{0, 1, 2}};
  EXPECT_THROW(build_topology(positions, past_the_end), Failure);
  const CasterTopology caster = build_topology(positions, triangle);
  std::vector<ShadowPlane> planes;
  EXPECT_THROW(append_shadow_planes(caster, std::span(positions).first(2), {}, planes), Failure);
  EXPECT_THROW(shadow_count(caster, std::span(positions).first(2), {}, {0, 0, 0}), Failure);
}

LightOrigin point_at(const glm::vec3& position) { return {false, position, {0, -1, 0}}; }
LightOrigin sun(const glm::vec3& direction) { return {true, {0, 0, 0}, direction}; }

// A UV sphere's bands are planar quads (isosceles trapezoids), so its silhouette follows
// whole rings and meridians: from a point on the axis one ring of 32 edges; a sun along −y
// the equator (32 edges); a sun along +x the meridians at ±90°, 16 edges each, which meet at
// the poles: 32 edges in one loop.
TEST(ShadowEdges, UvSphereSilhouetteIsOneLoopOfTwoSidedEdges) {
  const TestMesh mesh = uv_sphere(32, 16, "UV sphere");
  const CasterTopology caster = build_topology(mesh.positions, mesh.triangles);
  ASSERT_TRUE(caster.closed);
  const auto check = [&](const LightOrigin& light, std::optional<int> edges) {
    std::vector<ShadowPlane> planes;
    const ShadowPlaneStats stats = append_shadow_planes(caster, caster.positions, light, planes);
    EXPECT_EQ(stats.planes, static_cast<int>(planes.size()));
    EXPECT_EQ(stats.silhouette_edges, stats.planes);
    EXPECT_EQ(stats.boundary_edges, 0);
    for (const ShadowPlane& plane : planes) EXPECT_EQ(std::abs(plane.weight), 2);
    EXPECT_EQ(shadow_plane_loops(caster, caster.positions, light), 1);
    if (edges) {
      EXPECT_EQ(stats.silhouette_edges, *edges);
    }
    return stats.silhouette_edges;
  };
  check(point_at({0, 3, 0}), 32);
  check(sun({0, -1, 0}), 32);
  check(sun({1, 0, 0}), 32);
  // From anywhere else outside, the loop zigzags across bands and columns.
  std::mt19937 rng(3);
  int fewest = 1 << 30, most = 0;
  for (int k = 0; k < 200; ++k) {
    glm::vec3 position = random_point(rng, 6.0f);
    if (glm::length(position) < 1.1f) continue;
    const int edges = check(point_at(position), std::nullopt);
    fewest = std::min(fewest, edges);
    most = std::max(most, edges);
  }
  std::printf("UV sphere 32×16 from random points outside: %d to %d silhouette edges\n", fewest, most);
}

TEST(ShadowEdges, PlanesDoNotDependOnTriangleOrderOrWhereEachTriangleStarts) {
  std::mt19937 rng(11);
  for (TestMesh mesh : test_meshes(rng)) {
    const CasterTopology caster = build_topology(mesh.positions, mesh.triangles);
    std::shuffle(mesh.triangles.begin(), mesh.triangles.end(), rng);
    for (glm::uvec3& t : mesh.triangles) {
      const int r = static_cast<int>(rng() % 3);
      t = glm::uvec3(t[r], t[(r + 1) % 3], t[(r + 2) % 3]);
    }
    const CasterTopology shuffled = build_topology(mesh.positions, mesh.triangles);
    size_t planes = 0;
    for (const LightOrigin& light : random_lights(rng)) {
      std::vector<ShadowPlane> before, after;
      append_shadow_planes(caster, caster.positions, light, before);
      append_shadow_planes(shuffled, shuffled.positions, light, after);
      EXPECT_EQ(sorted(before), sorted(after)) << mesh.name;
      planes += before.size();
    }
    EXPECT_GT(planes, 0u) << mesh.name;
  }
}

}  // namespace
}  // namespace airlight::geometry
