#include "geometry/beam_tree_test_support.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace airlight::geometry {
namespace {

using namespace testing;

class BeamTreeLight : public ::testing::TestWithParam<LightCase> {};

INSTANTIATE_TEST_SUITE_P(Lights, BeamTreeLight, ::testing::ValuesIn(light_cases()),
                         [](const auto& info) { return info.param.name; });

TEST_P(BeamTreeLight, ClassifiesRandomPointsAsEmbreeDoesOutsideTheEpsilonBand) {
  const Light& light = GetParam().light;
  Tally total;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    Rng rng(seed);
    const Soup s = soup(rng);
    const Tally tally = classify_against_embree(light, with_backplate(s.polygons, light), 25000, rng);
    total.points += tally.points;
    total.skipped += tally.skipped;
    total.boundary += tally.boundary;
    total.wrong += tally.wrong;
  }
  std::printf("%-8s %d points: %d in the ε band (skipped), %d boundary outside it, %d wrong\n",
              GetParam().name.c_str(), total.points, total.skipped, total.boundary, total.wrong);
  EXPECT_EQ(total.wrong, 0);
  // A boundary answer outside the band means a plane of the tree lies within ε of p while
  // no true boundary lies within 2ε: the tree's planes are the true ones.
  EXPECT_EQ(total.boundary, 0);
}

TEST_P(BeamTreeLight, PartitionsPolygonsIntoLitAndShadowedPartsOfTheSameArea) {
  const Light& light = GetParam().light;
  int polygons = 0, parts = 0, samples = 0, skipped = 0, wrong = 0;
  double worst = 0.0;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    Rng rng(seed);
    const std::vector<BeamPolygon> scene = with_backplate(soup(rng).polygons, light);
    const double epsilon = beam_epsilon(light_origin(light), scene);
    const BeamTree tree(light_origin(light), scene, epsilon);
    const Truth truth(light, scene, epsilon);
    for (int q = 0; q < 150; ++q, ++polygons) {
      const BeamPolygon polygon{regular(sample_point(light, rng), unit(rng), uniform(rng, 0.2, 1.5), 3 + q % 4), q};
      std::vector<BeamPolygon> lit, shadowed;
      tree.partition(polygon, lit, shadowed);
      double sum = 0.0;
      for (const bool is_lit : {true, false})
        for (const BeamPolygon& part : is_lit ? lit : shadowed) {
          ++parts;
          EXPECT_EQ(part.source, q);
          sum += area(part.vertices);
          for (int k = 0; k < 8; ++k, ++samples) {
            const std::optional<bool> answer = truth.robust(sample_in(part.vertices, rng));
            skipped += !answer;
            wrong += answer && *answer != is_lit;
          }
        }
      worst = std::max(worst, std::abs(sum - area(polygon.vertices)) / area(polygon.vertices));
    }
  }
  std::printf("%-8s %d polygons, %d parts: %d samples, %d in the ε band, %d wrong; parts' area off by %.2e at most\n",
              GetParam().name.c_str(), polygons, parts, samples, skipped, wrong, worst);
  EXPECT_EQ(wrong, 0);
  // Parts are clipped, never dropped: their areas differ from the whole by the rounding of
  // each clip's vertices and each fan's cross products, 10⁻¹⁶ relative per operation over at
  // most a few hundred parts. A lost or doubled part would be a visible fraction.
  EXPECT_LT(worst, 1e-10);
}

TEST_P(BeamTreeLight, InsertionOrderDoesNotChangeTheLitVolume) {
  const Light& light = GetParam().light;
  int points = 0, boundary = 0, conflicts = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    Rng rng(seed);
    const std::vector<BeamPolygon> scene = with_backplate(soup(rng).polygons, light);
    std::vector<BeamPolygon> reversed(scene.rbegin(), scene.rend()), shuffled = scene;
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    const double epsilon = beam_epsilon(light_origin(light), scene);
    const BeamTree a(light_origin(light), scene, epsilon), b(light_origin(light), reversed, epsilon),
        c(light_origin(light), shuffled, epsilon);
    for (int k = 0; k < 25000; ++k, ++points) {
      const glm::dvec3 p = sample_point(light, rng);
      const Side sides[3] = {a.classify(p), b.classify(p), c.classify(p)};
      const bool definite[3] = {sides[0] != Side::boundary, sides[1] != Side::boundary, sides[2] != Side::boundary};
      boundary += !definite[0] || !definite[1] || !definite[2];
      for (int i = 0; i < 3; ++i) conflicts += definite[i] && definite[(i + 1) % 3] && sides[i] != sides[(i + 1) % 3];
    }
  }
  std::printf("%-8s %d points in 3 orders: %d boundary in some order, %d conflicting answers\n",
              GetParam().name.c_str(), points, boundary, conflicts);
  // Each tree answers lit or shadowed only outside ε of its own planes, which lie within
  // ε·|p − L|/R of the true boundaries: two definite answers cannot disagree.
  EXPECT_EQ(conflicts, 0);
}

// The ray the light sends through a random point of its influence: from L in a random
// direction (a spot's within its cone), or from a random point of a beam's aperture along D.
std::pair<glm::dvec3, glm::dvec3> light_ray(const Light& light, Rng& rng) {
  if (light.type == LightType::directional) {
    glm::dvec3 right, up;
    optics::gobo_frame(light, right, up);
    const Beam& beam = *light.beam;
    return {glm::dvec3(beam.origin) + uniform(rng, -0.5, 0.5) * beam.size.x * right +
                uniform(rng, -0.5, 0.5) * beam.size.y * up,
            travel(light)};
  }
  return {glm::dvec3(light.position), glm::normalize(sample_point(light, rng) - glm::dvec3(light.position))};
}

// The farthest vertex from a point light: the tree's far radius R.
double far_radius(const Light& light, const std::vector<BeamPolygon>& scene) {
  double far = 0.0;
  for (const BeamPolygon& polygon : scene)
    for (const glm::dvec3& v : polygon.vertices) far = std::max(far, glm::distance(v, glm::dvec3(light.position)));
  return far;
}

TEST_P(BeamTreeLight, VisibleSetIsLitAndCoversTheInfluenceOnce) {
  const Light& light = GetParam().light;
  int pieces = 0, samples = 0, skipped_samples = 0, unlit = 0, rays = 0, skipped_rays = 0, ties = 0;
  double worst_coverage = 0.0;  // a face's |covered − its coverage| over its bound
  for (unsigned seed = 1; seed <= 3; ++seed) {
    Rng rng(seed);
    const std::vector<BeamPolygon> scene = with_backplate(soup(rng).polygons, light);
    const double epsilon = beam_epsilon(light_origin(light), scene);
    const BeamTree tree(light_origin(light), scene, epsilon);
    const Truth truth(light, scene, epsilon);
    const std::vector<BeamPolygon>& visible = tree.visible_set();
    pieces += static_cast<int>(visible.size());

    // Within each backplate face's beam the pieces cover what the face covers, once: a piece
    // lies within ε·|x − L|/R of its leaf (ε across D), so the sum may be off by that times
    // the pieces' perimeters.
    const double band = light.type == LightType::directional ? epsilon : epsilon / far_radius(light, scene);
    for (const BeamPolygon& face : influence_backplate(light, kFar)) {
      double covered = 0.0, perimeter = 0.0;
      for (const BeamPolygon& piece : visible) {
        const std::vector<glm::dvec3> part = clip_to_beam(piece.vertices, face.vertices, light);
        if (part.size() < 3) continue;
        covered += coverage(light, part);
        perimeter += seen_perimeter(light, part);
      }
      const double off = std::abs(covered - coverage(light, face.vertices));
      EXPECT_LE(off, band * perimeter) << "seed " << seed;
      worst_coverage = std::max(worst_coverage, off / (band * perimeter));
    }

    // Each piece is lit: a point of it, moved toward the light until it is 10ε off the piece's
    // plane (beyond Truth's 4ε steps), sees the light; its path to the light is the point's.
    for (const BeamPolygon& piece : visible)
      for (int k = 0; k < 3; ++k, ++samples) {
        const glm::dvec3 x = sample_in(piece.vertices, rng), n = glm::normalize(twice_area(piece.vertices));
        const glm::dvec3 up = toward_light(light, x);
        const std::optional<bool> lit = truth.robust(x + 10.0 * epsilon / std::abs(glm::dot(n, up)) * up);
        skipped_samples += !lit;
        unlit += lit && !*lit;
      }

    // Each ray of light meets exactly one piece, where Embree finds the first surface.
    for (int k = 0; k < 3000; ++k, ++rays) {
      const auto [origin, dir] = light_ray(light, rng);
      int count = 0, source = 0;
      double t = 0.0;
      bool near_edge = false;
      for (const BeamPolygon& piece : visible) {
        const std::optional<Crossing> c = crossing(piece.vertices, origin, dir);
        if (!c || c->inside < -4.0 * epsilon) continue;
        near_edge = near_edge || c->inside <= 4.0 * epsilon;
        if (c->inside > 4.0 * epsilon) std::tie(count, source, t) = std::tuple(count + 1, piece.source, c->t);
      }
      if (near_edge) {
        ++skipped_rays;
        continue;
      }
      ASSERT_EQ(count, 1) << "seed " << seed << " ray " << k;
      const std::optional<Occluders::Hit> hit = truth.occluders().first(origin, dir);
      ASSERT_TRUE(hit);
      // Embree intersects in float: t errs by a few ulps of coordinates up to 16 m (2·10⁻⁶ m).
      EXPECT_NEAR(hit->t, t, 1e-4);
      if (scene[hit->polygon].source == source) continue;
      // Embree found another polygon at the same depth (coplanar, or crossing there): a tie.
      ++ties;
      EXPECT_TRUE(std::any_of(scene.begin(), scene.end(), [&](const BeamPolygon& polygon) {
        const std::optional<Crossing> c = crossing(polygon.vertices, origin, dir);
        return polygon.source == source && c && c->inside > -4.0 * epsilon && std::abs(c->t - hit->t) <= 1e-4;
      })) << "seed " << seed << " ray " << k;
    }
  }
  std::printf("%-8s %d visible pieces: coverage off by %.2g of its bound; %d samples, %d in the ε band, %d unlit; "
              "%d rays, %d near a piece's edge, %d ties\n",
              GetParam().name.c_str(), pieces, worst_coverage, samples, skipped_samples, unlit, rays, skipped_rays, ties);
  EXPECT_EQ(unlit, 0);
}

// ---- Small scenes worked by hand ----

BeamPolygon square_at(double z, double half, int source) {
  return {{{-half, -half, z}, {half, -half, z}, {half, half, z}, {-half, half, z}}, source};
}

double area_of(const std::vector<BeamPolygon>& polygons, int source) {
  double sum = 0.0;
  for (const BeamPolygon& polygon : polygons) sum += polygon.source == source ? area(polygon.vertices) : 0.0;
  return sum;
}

// Areas here are sums of a few fan cross products of coordinates ≤ 4 m: rounding 10⁻¹⁴ m².
constexpr double kAreaRounding = 1e-12;

TEST(BeamTree, SquareOverAFloorShadowsItsProjectionFromAPoint) {
  Light light;
  light.position = {0.0f, 0.0f, 2.0f};
  const std::vector<BeamPolygon> scene = {square_at(0.0, 1.0, 0), square_at(-1.0, 4.0, 1)};
  const double epsilon = beam_epsilon(light_origin(light), scene);
  const BeamTree tree(light_origin(light), scene, epsilon);

  // From z = 2 the square's edges x, y = ±1 at z = 0 reach ±(2 − z)/2: ±1.25 at z = −0.5,
  // ±1.5 on the floor.
  EXPECT_EQ(tree.classify({0, 0, 1}), Side::lit);
  EXPECT_EQ(tree.classify({0, 0, -0.5}), Side::shadowed);
  EXPECT_EQ(tree.classify({3, 0, -0.5}), Side::lit);
  EXPECT_EQ(tree.classify({1.25 + 1e-3, 0.3, -0.5}), Side::lit);
  EXPECT_EQ(tree.classify({1.25 - 1e-3, 0.3, -0.5}), Side::shadowed);
  EXPECT_EQ(tree.classify({1.25, 0.3, -0.5}), Side::boundary);  // on the plane through L and x = 1
  EXPECT_EQ(tree.classify({0.5, 0.5, 0}), Side::boundary);      // on the square
  EXPECT_EQ(tree.classify({3, 0, -2}), Side::shadowed);         // under the floor
  EXPECT_EQ(tree.classify({10, 0, -2}), Side::lit);             // beyond the floor's beam

  // Seen from L: all of the square, the floor less the square's shadow [−1.5, 1.5]².
  EXPECT_NEAR(area_of(tree.visible_set(), 0), 4.0, kAreaRounding);
  EXPECT_NEAR(area_of(tree.visible_set(), 1), 64.0 - 9.0, kAreaRounding);
  // The square: 4 planes, each with an open leaf, and its solid leaf, under the root. The floor
  // reaches the 4 open leaves as 4 pieces, which have 3, 2, 2 and 1 edges that no plane holds:
  // 8 more planes with their open leaves.
  EXPECT_EQ(tree.node_count(), 1 + 2 * 4 + 2 * 8);

  std::vector<BeamPolygon> lit, shadowed;
  tree.partition(square_at(-0.5, 4.0, 7), lit, shadowed);
  EXPECT_NEAR(area_of(shadowed, 7), 2.5 * 2.5, kAreaRounding);
  EXPECT_NEAR(area_of(lit, 7), 64.0 - 2.5 * 2.5, kAreaRounding);
}

TEST(BeamTree, SquareOverAFloorShadowsItsOwnShapeAlongD) {
  Light light;
  light.type = LightType::directional;
  light.direction = {0.0f, 0.0f, -1.0f};
  const std::vector<BeamPolygon> scene = {square_at(0.0, 1.0, 0), square_at(-1.0, 4.0, 1)};
  const BeamTree tree(light_origin(light), scene, beam_epsilon(light_origin(light), scene));
  EXPECT_EQ(tree.classify({0.99, 0, -0.5}), Side::shadowed);
  EXPECT_EQ(tree.classify({1.01, 0, -0.5}), Side::lit);
  EXPECT_EQ(tree.classify({0, 0, 5}), Side::lit);
  EXPECT_NEAR(area_of(tree.visible_set(), 1), 64.0 - 4.0, kAreaRounding);
  std::vector<BeamPolygon> lit, shadowed;
  tree.partition(square_at(-0.5, 4.0, 7), lit, shadowed);
  EXPECT_NEAR(area_of(shadowed, 7), 4.0, kAreaRounding);
}

// ---- Degenerate input ----

// Zero-area polygons around a and b: collinear, repeated corners, too few corners, corners
// closer than ε, a sliver 10⁻⁹ wide. ε is about 10⁻⁵ in the scenes below.
std::vector<std::vector<glm::dvec3>> zero_area(const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 across = glm::normalize(glm::cross(b - a, glm::dvec3(0.3, 1, 0.2)));
  return {{a, 0.5 * (a + b), b}, {a, b, b}, {a, a, a}, {a, b}, {a}, {}, {a, a + 1e-9 * across, b},
          {a, b, 0.5 * (a + b) + 1e-9 * across}};
}

// Random triangles over a floor and the given polygons, with the light's backplate.
std::vector<BeamPolygon> with_occluders(const Light& light, const std::vector<std::vector<glm::dvec3>>& extra) {
  Rng rng(10);
  Soup s;
  for (int k = 0; k < 20; ++k) {
    const glm::dvec3 c = in_box(rng, 2.0);
    s.add({c + 0.7 * unit(rng), c + 0.7 * unit(rng), c + 0.7 * unit(rng)});
  }
  s.add(square_at(-2.5, 3.0, 0).vertices);
  for (const std::vector<glm::dvec3>& polygon : extra) s.add(polygon);
  return with_backplate(s.polygons, light);
}

// The tree skips what it should, and skipping leaves the tree it builds without them.
void expect_skipped(const Light& light, const std::vector<std::vector<glm::dvec3>>& skipped,
                    const std::vector<std::vector<glm::dvec3>>& kept, int zero_area, int edge_on) {
  std::vector<std::vector<glm::dvec3>> all = skipped;
  all.insert(all.end(), kept.begin(), kept.end());
  const std::vector<BeamPolygon> with = with_occluders(light, all), without = with_occluders(light, kept);
  const double epsilon = beam_epsilon(light_origin(light), with);
  const BeamTree tree(light_origin(light), with, epsilon), reference(light_origin(light), without, epsilon);
  EXPECT_EQ(tree.stats().zero_area, zero_area);
  EXPECT_EQ(tree.stats().edge_on, edge_on);
  EXPECT_EQ(tree.node_count(), reference.node_count());
  Rng rng(13);
  int differ = 0;
  for (int k = 0; k < 20000; ++k) {
    const glm::dvec3 p = in_box(rng, 3.0);
    differ += tree.classify(p) != reference.classify(p);
  }
  EXPECT_EQ(differ, 0);
}

void expect_classification_as_embree(const Light& light, const std::vector<BeamPolygon>& scene) {
  Rng rng(14);
  const Tally tally = classify_against_embree(light, scene, 50000, rng);
  std::printf("degenerate, %s: %d points: %d in the ε band, %d boundary outside it, %d wrong\n",
              light.type == LightType::directional ? "directional" : "point", tally.points, tally.skipped,
              tally.boundary, tally.wrong);
  EXPECT_EQ(tally.wrong, 0);
  EXPECT_EQ(tally.boundary, 0);
}

TEST(BeamTree, DegeneratePolygonsAreSkippedAndCountedAroundAPointLight) {
  Rng rng(11);
  Light light;
  light.position = {0.2f, 0.5f, -0.1f};
  const glm::dvec3 l(light.position), u = glm::normalize(glm::dvec3(1, 0.2, -0.3)),
      v = glm::normalize(glm::cross(u, glm::dvec3(0, 0, 1))), w = glm::cross(u, v);
  std::vector<std::vector<glm::dvec3>> skipped = zero_area(in_box(rng, 2.0), in_box(rng, 2.0));
  // Edge-on: in a plane through L, away from it; 10⁻¹¹ off such a plane; a sliver along a
  // line through L.
  skipped.push_back({l + u + 0.2 * v, l + 2.0 * u, l + 1.5 * u + 0.7 * v});
  skipped.push_back({l + u + 1e-11 * w, l + 2.0 * u + 1e-11 * w, l + 1.5 * u + 0.7 * v + 1e-11 * w});
  skipped.push_back({l - u, l - 2.0 * u, l - 1.5 * u + 1e-3 * v});
  // Within ε of L: around it (in its plane to rounding); 10⁻⁶ off it.
  const std::vector<glm::dvec3> around = {l - 0.5 * u - 0.3 * v, l + 0.5 * u - 0.3 * v, l + 0.4 * v};
  skipped.push_back(around);
  skipped.push_back({around[0] + 1e-6 * w, around[1] + 1e-6 * w, around[2] + 1e-6 * w});
  // Kept: 10⁻³ off a plane through L; a sliver 10⁻³ wide; a quad with a corner given twice.
  const std::vector<std::vector<glm::dvec3>> kept = {
      {l + u + 1e-3 * w, l + 2.0 * u + 1e-3 * w, l + 1.5 * u + 0.7 * v + 1e-3 * w},
      {l - u + 0.5 * w, l - 2.0 * u + 0.5 * w, l - 1.5 * u + 0.5 * w + 1e-3 * v},
      {l - w, l - w + u, l - w + u, l - w + u + v, l - w + v}};
  expect_skipped(light, skipped, kept, 8, 5);
  // Embree sees the skipped polygons but those within ε of L: the tree takes the light to be
  // on neither side of them, and with them every path to L would be in the ε band.
  skipped.resize(skipped.size() - 2);
  skipped.insert(skipped.end(), kept.begin(), kept.end());
  expect_classification_as_embree(light, with_occluders(light, skipped));
}

TEST(BeamTree, DegeneratePolygonsAreSkippedAndCountedUnderADirectionalLight) {
  Rng rng(12);
  Light light;
  light.type = LightType::directional;
  light.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.4f));
  const glm::dvec3 d = travel(light), u = glm::normalize(glm::cross(d, glm::dvec3(1, 0, 0)));
  light.beam = Beam{glm::vec3(-6.0 * d), {7.0f, 7.0f}, 12.0f};
  std::vector<std::vector<glm::dvec3>> skipped = zero_area(in_box(rng, 2.0), in_box(rng, 2.0));
  // Edge-on: along D; tilted 10⁻¹¹ off D. Kept: tilted 10⁻³.
  const glm::dvec3 a = in_box(rng, 1.0);
  const auto tilted = [&](double tilt) { return std::vector<glm::dvec3>{a, a + d + tilt * glm::cross(d, u), a + 0.5 * d + u}; };
  skipped.push_back(tilted(0.0));
  skipped.push_back(tilted(1e-11));
  expect_skipped(light, skipped, {tilted(1e-3)}, 8, 2);
  skipped.push_back(tilted(1e-3));
  expect_classification_as_embree(light, with_occluders(light, skipped));
}

TEST(BeamTree, SkipsASliverWhoseSideOfThePointLightRoundingHides) {
  // A sliver 2 m long and 2·10⁻⁹ wide, 10⁻⁴ from L: its normal may be off by about
  // 10⁻¹⁶·2/(2·10⁻⁹) rad, L's height over its plane by 10⁻⁷ m. At 10⁻⁹ m L's side is
  // unknown (skipped); at 10⁻³ m it is not (kept). With ε = 10⁻⁹ neither is narrower than ε
  // nor thinner than ε seen from L.
  Light light;
  light.position = {0.0f, 0.0f, 0.0f};
  for (const double height : {1e-9, 1e-3}) {
    const std::vector<BeamPolygon> sliver = {{{{1e-4, 0, height}, {2, 0, height}, {1, 2e-9, height}}, 0}};
    const BeamTree tree(light_origin(light), sliver, 1e-9);
    EXPECT_EQ(tree.stats().zero_area, 0) << height;
    EXPECT_EQ(tree.stats().edge_on, height < 1e-6) << height;
    EXPECT_EQ(tree.visible_set().size(), height < 1e-6 ? 0u : 1u) << height;
  }
}

TEST(BeamTree, RefusesNonFiniteAndNonPlanarPolygonsAndABadEpsilon) {
  Light light;
  const LightOrigin origin = light_origin(light);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<BeamPolygon> non_finite = {{{{0, 0, 1}, {1, 0, 1}, {0, nan, 1}}, 0}};
  EXPECT_THROW(BeamTree(origin, non_finite, 1e-6), Failure);
  std::vector<BeamPolygon> bent = {square_at(-1.0, 1.0, 0)};
  bent[0].vertices[2].z += 1e-3;  // 10³ times ε off the others' plane
  EXPECT_THROW(BeamTree(origin, bent, 1e-6), Failure);
  for (const double epsilon : {0.0, -1e-6, nan, std::numeric_limits<double>::infinity()})
    EXPECT_THROW(BeamTree(origin, {}, epsilon), Failure) << epsilon;
}

// ---- The backplate ----

// Whether the ray from `origin` along `dir` meets one of the faces. A base circumscribing a
// cone touches the rim's rays at its edges' midpoints, so up to rounding at 8 m (10⁻¹⁴ m).
bool meets(const std::vector<BeamPolygon>& faces, const glm::dvec3& origin, const glm::dvec3& dir) {
  return std::any_of(faces.begin(), faces.end(), [&](const BeamPolygon& face) {
    const std::optional<Crossing> c = crossing(face.vertices, origin, dir);
    return c && c->inside >= -1e-12;
  });
}

TEST(BeamTree, BackplateClosesEveryLightsInfluence) {
  const glm::dvec3 position(0.3, -0.2, 0.5);
  Light point;
  point.position = position;
  const std::vector<BeamPolygon> cube = influence_backplate(point, kFar);
  ASSERT_EQ(cube.size(), 6u);
  double total = 0.0;
  for (const BeamPolygon& face : cube) {
    EXPECT_EQ(face.source, -1);
    total += coverage(point, face.vertices);
  }
  EXPECT_NEAR(total, 4.0 * std::numbers::pi, 1e-12);  // rounding of six atan2

  // A spot's faces are those its cone reaches; every direction on the cone's rim meets one.
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.2, -1.0, 0.3));
  for (const auto& [cone, faces] : {std::pair(30.0f, 1u), std::pair(45.0f, 1u), std::pair(60.0f, 5u),
                                    std::pair(125.0f, 5u), std::pair(126.0f, 6u), std::pair(180.0f, 6u)}) {
    const Light light = spot(position, axis, cone);
    const std::vector<BeamPolygon> backplate = influence_backplate(light, kFar);
    EXPECT_EQ(backplate.size(), faces) << cone;
    glm::dvec3 right, up;
    optics::gobo_frame(light, right, up);
    const double angle = std::min(cone * std::numbers::pi / 180.0, std::numbers::pi - 1e-9);
    for (int k = 0; k < 360; ++k) {
      const double around = 2.0 * std::numbers::pi * k / 360.0;
      const glm::dvec3 dir =
          std::cos(angle) * travel(light) + std::sin(angle) * (std::cos(around) * right + std::sin(around) * up);
      EXPECT_TRUE(meets(backplate, glm::dvec3(light.position), dir)) << cone << "° at " << k << "°";
    }
  }
  // The 30° spot's base circumscribes the cone: half-size far·tan 30°, 4·asin(sin² 30°) sr.
  EXPECT_NEAR(coverage(spot(position, axis, 30.0f), influence_backplate(spot(position, axis, 30.0f), kFar)[0].vertices),
              4.0 * std::asin(0.25), 1e-12);

  // A beam: the far face of its box, the aperture moved `length` downstream.
  const Light beam = light_cases()[3].light;
  const std::vector<BeamPolygon> far_face = influence_backplate(beam, kFar);
  ASSERT_EQ(far_face.size(), 1u);
  EXPECT_NEAR(coverage(beam, far_face[0].vertices), 5.0 * 4.5, 1e-12);
  glm::dvec3 centre(0.0);
  for (const glm::dvec3& x : far_face[0].vertices) centre += 0.25 * x;
  EXPECT_NEAR(glm::distance(centre, glm::dvec3(beam.beam->origin) + 12.0 * travel(beam)), 0.0, 1e-12);

  // An unbounded directional light: a square 2·far wide, far downstream of the origin.
  Light sun = beam;
  sun.beam.reset();
  const std::vector<BeamPolygon> sun_face = influence_backplate(sun, kFar);
  ASSERT_EQ(sun_face.size(), 1u);
  EXPECT_NEAR(coverage(sun, sun_face[0].vertices), 4.0 * kFar * kFar, 1e-12);
}

// ---- Scale ----

// n small triangles in [-1, 1]³, sized so that each crosses about one other.
std::vector<BeamPolygon> small_soup(int n, Rng& rng) {
  const double size = 1.5 / std::cbrt(static_cast<double>(n));
  Soup s;
  for (int k = 0; k < n; ++k) {
    const glm::dvec3 c = in_box(rng, 1.0);
    s.add({c + size * in_box(rng, 1.0), c + size * in_box(rng, 1.0), c + size * in_box(rng, 1.0)});
  }
  return s.polygons;
}

// A unit UV sphere of about n triangles (two per grid quad; the poles' are zero-area).
std::vector<BeamPolygon> uv_sphere(int n) {
  const int segments = std::max(4, static_cast<int>(std::sqrt(static_cast<double>(n)))), rows = std::max(2, n / (2 * segments));
  const auto at = [&](int k, int j) {
    const double theta = std::numbers::pi * k / rows, phi = 2.0 * std::numbers::pi * j / segments;
    return glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
  };
  Soup s;
  for (int k = 0; k < rows; ++k)
    for (int j = 0; j < segments; ++j) {
      s.add({at(k, j), at(k + 1, j), at(k + 1, j + 1)});
      s.add({at(k, j), at(k + 1, j + 1), at(k, j + 1)});
    }
  return s.polygons;
}

// Build times, printed (not asserted): the sort's tree is O(log n) deep, and a beam tree over
// triangles in front-to-back order stays a few hundred nodes deep here.
void builds_and_covers_once(std::initializer_list<int> sizes) {
  std::printf("%-6s %7s %9s %8s %8s %8s %6s %5s %9s\n", "scene", "tris", "build s", "nodes", "visible", "pieces", "depth",
              "thin", "4π off");
  for (const bool sphere : {false, true})
    for (const int n : sizes) {
      Rng rng(static_cast<unsigned>(n));
      Light light;
      light.position = sphere ? glm::vec3(2.5f, 1.5f, 0.7f) : glm::vec3(0.3f, 0.2f, 0.1f);
      const std::vector<BeamPolygon> scene = with_backplate(sphere ? uv_sphere(n) : small_soup(n, rng), light);
      const double epsilon = beam_epsilon(light_origin(light), scene);
      const auto start = std::chrono::steady_clock::now();
      const BeamTree tree(light_origin(light), scene, epsilon);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      // As VisibleSetIsLitAndCoversTheInfluenceOnce: 4π, off by at most ε/R times the perimeters.
      double covered = 0.0, perimeter = 0.0;
      for (const BeamPolygon& piece : tree.visible_set()) {
        covered += coverage(light, piece.vertices);
        perimeter += seen_perimeter(light, piece.vertices);
      }
      EXPECT_NEAR(covered, 4.0 * std::numbers::pi, epsilon / far_radius(light, scene) * perimeter) << n;
      std::printf("%-6s %7zu %9.3f %8d %8zu %8d %6d %5d %9.1e\n", sphere ? "sphere" : "soup", scene.size() - 6, seconds,
                  tree.node_count(), tree.visible_set().size(), tree.stats().sorted_pieces, tree.stats().depth,
                  tree.stats().thin_pieces, covered - 4.0 * std::numbers::pi);
    }
}

// Enough pieces for the tree to grow in sectors, each on its own: together they answer as one
// tree would, the sector planes nowhere taken for a boundary.
TEST_P(BeamTreeLight, ATreeGrownInSectorsClassifiesAsEmbreeDoes) {
  const Light& light = GetParam().light;
  Rng rng(20000);
  const std::vector<BeamPolygon> scene = with_backplate(small_soup(20000, rng), light);
  const double epsilon = beam_epsilon(light_origin(light), scene);
  const BeamTree tree(light_origin(light), scene, epsilon);
  const Tally tally = classify_against_embree(tree, light, scene, epsilon, 20000, rng);
  std::printf("%-8s %d sectors, %d points: %d in the ε band (skipped), %d boundary outside it, %d wrong\n",
              GetParam().name.c_str(), tree.stats().sectors, tally.points, tally.skipped, tally.boundary, tally.wrong);
  EXPECT_GE(tree.stats().sectors, 4);
  EXPECT_EQ(tally.wrong, 0);
  EXPECT_EQ(tally.boundary, 0);
}

TEST(BeamTree, BuildsTenThousandTrianglesAndItsVisibleSetCoversTheSphereOnce) {
  builds_and_covers_once({100, 1000, 10000});
}

// Release only (CMakeLists.txt): under AddressSanitizer the 10⁵ builds took 46 s of the
// sanitizer suite, and the memory they use the 10⁴ ones already exercise.
TEST(BeamTree, BuildsAHundredThousandTrianglesAndItsVisibleSetCoversTheSphereOnce) {
  builds_and_covers_once({100000});
}

}  // namespace
}  // namespace airlight::geometry
