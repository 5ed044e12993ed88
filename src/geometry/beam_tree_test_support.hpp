#pragma once
// What the beam tree's tests share (beam_tree_test.cpp): Embree as the ground
// truth, seeded polygon soups and lights, measures of polygons, and the tally
// of a tree's classification against Embree.
#include "geometry/beam_tree.hpp"
#include "geometry/influence_backplate.hpp"
#include "optics/light.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <embree3/rtcore.h>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <optional>
#include <ostream>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace airlight::geometry::testing {

using Side = BeamTree::Side;

// Far enough that every backplate lies outside the soups' box [-3, 3]³ seen from any light here.
constexpr double kFar = 8.0;

// ---- Embree, the ground truth ----

// The polygons as fans of Embree triangles (float, robust traversal).
class Occluders {
public:
  explicit Occluders(std::span<const BeamPolygon> polygons)
      : device_(rtcNewDevice(nullptr)), scene_(rtcNewScene(device_)) {
    std::vector<glm::vec3> vertices;
    std::vector<glm::uvec3> triangles;
    for (size_t k = 0; k < polygons.size(); ++k) {
      const std::vector<glm::dvec3>& v = polygons[k].vertices;
      for (size_t i = 1; i + 1 < v.size(); ++i) {
        const auto first = static_cast<unsigned>(vertices.size());
        vertices.insert(vertices.end(), {glm::vec3(v[0]), glm::vec3(v[i]), glm::vec3(v[i + 1])});
        triangles.emplace_back(first, first + 1, first + 2);
        polygon_.push_back(static_cast<int>(k));
      }
    }
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    std::memcpy(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                        sizeof(glm::vec3), vertices.size()),
                vertices.data(), vertices.size() * sizeof(glm::vec3));
    std::memcpy(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                        sizeof(glm::uvec3), triangles.size()),
                triangles.data(), triangles.size() * sizeof(glm::uvec3));
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
  }
  ~Occluders() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  Occluders(const Occluders&) = delete;
  Occluders& operator=(const Occluders&) = delete;

  bool blocked(const glm::dvec3& origin, const glm::dvec3& dir, double t_far) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = make_ray(origin, dir, t_far);
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0.0f;
  }

  struct Hit {
    int polygon;
    double t;
  };
  std::optional<Hit> first(const glm::dvec3& origin, const glm::dvec3& dir) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit query{};
    query.ray = make_ray(origin, dir, std::numeric_limits<double>::infinity());
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &query);
    if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    return Hit{polygon_[query.hit.primID], query.ray.tfar};
  }

private:
  static RTCRay make_ray(const glm::dvec3& origin, const glm::dvec3& dir, double t_far) {
    RTCRay ray{};
    ray.org_x = static_cast<float>(origin.x);
    ray.org_y = static_cast<float>(origin.y);
    ray.org_z = static_cast<float>(origin.z);
    ray.dir_x = static_cast<float>(dir.x);
    ray.dir_y = static_cast<float>(dir.y);
    ray.dir_z = static_cast<float>(dir.z);
    ray.tfar = static_cast<float>(t_far);
    ray.mask = ~0u;
    return ray;
  }

  RTCDevice device_;
  RTCScene scene_;
  std::vector<int> polygon_;  // per Embree triangle
};

// The way a light travels, unit in double (the scene's float vector is unit to 6·10⁻⁸).
inline glm::dvec3 travel(const Light& light) { return glm::normalize(glm::dvec3(light.direction)); }

inline glm::dvec3 toward_light(const Light& light, const glm::dvec3& p) {
  return light.type == LightType::directional ? -travel(light) : glm::normalize(glm::dvec3(light.position) - p);
}

// Whether p is lit by Embree's rays: the segment to L, or the ray toward −D, is clear. The
// segment stops 10⁻⁶ of its length short of L, so a polygon through L (which the tree skips
// as edge-on) does not end every segment.
class Truth {
public:
  Truth(const Light& light, std::span<const BeamPolygon> polygons, double epsilon)
      : light_(light), occluders_(polygons), epsilon_(epsilon) {}

  bool lit(const glm::dvec3& p, const glm::dvec3& offset = glm::dvec3(0.0)) const {
    if (light_.type == LightType::directional)
      return !occluders_.blocked(p, -travel(light_), std::numeric_limits<double>::infinity());
    return !occluders_.blocked(p, glm::dvec3(light_.position) + offset - p, 1.0 - 1e-6);
  }

  // lit(p), or nothing when p lies in the ε band: when moving p, or a point light by
  // `offset`, 2ε or 4ε along an axis changes the answer. The tree answers lit or shadowed
  // wrongly only within ε·|p − L|/R ≤ ε of a true boundary (a plane through L and an edge, or
  // a surface) plus ε, its own band; some axis step of 4ε crosses any plane within
  // 4ε/√3 = 2.3ε of p, and the 2ε steps catch shadows thinner than the 4ε steps, which could
  // jump over them. Moving L catches polygons within ε of it, which the tree skips.
  std::optional<bool> robust(const glm::dvec3& p) const {
    const bool answer = lit(p);
    for (const double step : {2.0 * epsilon_, 4.0 * epsilon_})
      for (int axis = 0; axis < 3; ++axis)
        for (const double sign : {-1.0, 1.0}) {
          glm::dvec3 q = p, offset(0.0);
          q[axis] += sign * step;
          offset[axis] = sign * step;
          if (lit(q) != answer) return std::nullopt;
          if (light_.type != LightType::directional && lit(p, offset) != answer) return std::nullopt;
        }
    return answer;
  }

  const Occluders& occluders() const { return occluders_; }

private:
  Light light_;
  Occluders occluders_;
  double epsilon_;
};

// ---- Scenes ----

using Rng = std::mt19937;

inline double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

inline glm::dvec3 in_box(Rng& rng, double half) {
  const double x = uniform(rng, -half, half), y = uniform(rng, -half, half), z = uniform(rng, -half, half);
  return {x, y, z};
}

inline glm::dvec3 unit(Rng& rng) {
  glm::dvec3 v;
  do v = in_box(rng, 1.0);
  while (glm::length(v) > 1.0 || glm::length(v) < 0.1);
  return glm::normalize(v);
}

struct Soup {
  std::vector<BeamPolygon> polygons;
  void add(std::vector<glm::dvec3> vertices) {
    polygons.push_back({std::move(vertices), static_cast<int>(polygons.size())});
  }
};

// A regular convex polygon of `corners` corners and circumradius r about c in the plane ⟂ n.
inline std::vector<glm::dvec3> regular(const glm::dvec3& c, const glm::dvec3& n, double r, int corners) {
  const glm::dvec3 u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 v = glm::cross(n, u);
  std::vector<glm::dvec3> out;
  for (int k = 0; k < corners; ++k) {
    const double a = 2.0 * std::numbers::pi * k / corners;
    out.push_back(c + r * (std::cos(a) * u + std::sin(a) * v));
  }
  return out;
}

inline void add_box(Soup& soup, const glm::dvec3& lo, const glm::dvec3& hi) {
  // Corner c has x from bit 0, y from bit 1, z from bit 2.
  constexpr int faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (const auto& face : faces) {
    std::vector<glm::dvec3> v;
    for (const int c : face) v.emplace_back(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z);
    soup.add(v);
  }
}

// Polygons in [-2.5, 2.5]³: random triangles, small to large, that cross one another;
// coplanar overlapping ones and an exact duplicate; a height-field patch whose triangles
// share edges; a closed box; convex quads and pentagons; slivers 10⁻³ wide (kept) and
// 10⁻⁹ wide (narrower than ε); a collinear triangle, one with a repeated vertex, a two-vertex
// polygon, a quad given with one corner twice.
inline Soup soup(Rng& rng) {
  Soup s;
  for (int k = 0; k < 40; ++k) {
    const glm::dvec3 c = in_box(rng, 2.0);
    const double size = uniform(rng, 0.1, 1.5);
    s.add({c + size * unit(rng), c + size * unit(rng), c + size * unit(rng)});
  }
  for (int k = 0; k < 5; ++k) s.add({in_box(rng, 2.5), in_box(rng, 2.5), in_box(rng, 2.5)});
  const auto flat = [&] { return glm::dvec3(uniform(rng, -1.5, 1.5), 0.3, uniform(rng, -1.5, 1.5)); };
  for (int k = 0; k < 4; ++k) s.add({flat(), flat(), flat()});
  s.add(s.polygons.back().vertices);
  const glm::dvec3 corner = in_box(rng, 1.5);
  const auto height = [&](int i, int j) { return corner + glm::dvec3(0.3 * i, 0.15 * std::sin(3.0 * i + j), 0.3 * j); };
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j) {
      s.add({height(i, j), height(i + 1, j), height(i + 1, j + 1)});
      s.add({height(i, j), height(i + 1, j + 1), height(i, j + 1)});
    }
  const glm::dvec3 lo = in_box(rng, 1.5);
  add_box(s, lo, lo + glm::dvec3(0.6, 0.4, 0.5));
  for (const int corners : {4, 4, 5, 5}) s.add(regular(in_box(rng, 2.0), unit(rng), uniform(rng, 0.2, 1.0), corners));
  for (const double width : {1e-3, 1e-9}) {
    const glm::dvec3 a = in_box(rng, 2.0), b = in_box(rng, 2.0);
    const glm::dvec3 across = glm::normalize(glm::cross(b - a, unit(rng)));
    s.add({a, b, 0.5 * (a + b) + width * across});
  }
  const glm::dvec3 a = in_box(rng, 2.0), b = in_box(rng, 2.0);
  s.add({a, 0.5 * (a + b), b});
  s.add({a, b, b});
  s.add({a, b});
  std::vector<glm::dvec3> quad = regular(in_box(rng, 2.0), unit(rng), 0.5, 4);
  quad.insert(quad.begin() + 2, quad[1]);
  s.add(quad);
  return s;
}

// ---- Lights ----

struct LightCase {
  std::string name;
  Light light;
};

// gtest names a case by it, instead of the struct's bytes.
inline void PrintTo(const LightCase& c, std::ostream* os) { *os << c.name; }

inline Light spot(const glm::dvec3& position, const glm::dvec3& axis, float cone_deg) {
  Light light;
  light.type = LightType::spot;
  light.position = position;
  light.direction = glm::normalize(axis);
  light.cone_deg = cone_deg;
  return light;
}

inline std::vector<LightCase> light_cases() {
  Light point;
  point.position = {0.4f, 0.7f, -0.3f};
  Light sun;
  sun.type = LightType::directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  sun.beam = Beam{-6.0f * sun.direction, {5.0f, 4.5f}, 12.0f};
  return {{"point", point},
          {"spot30", spot({0.5, 2.6, 0.2}, {-0.1, -1.0, 0.05}, 30.0f)},
          {"spot100", spot({-0.3, 0.1, 0.6}, {0.3, 0.2, -1.0}, 100.0f)},
          {"beam", sun}};
}

// A point where the light reaches: in a spot's cone up to 5 m from it, else in [-3, 3]³.
inline glm::dvec3 sample_point(const Light& light, Rng& rng) {
  if (light.type != LightType::spot) return in_box(rng, 3.0);
  const glm::dvec3 axis = travel(light);
  glm::dvec3 u;
  do u = unit(rng);
  while (glm::dot(u, axis) < std::cos(light.cone_deg * std::numbers::pi / 180.0));
  return glm::dvec3(light.position) + uniform(rng, 0.0, 5.0) * u;
}

// The soup with the light's backplate.
inline std::vector<BeamPolygon> with_backplate(std::vector<BeamPolygon> polygons, const Light& light) {
  for (BeamPolygon& face : influence_backplate(light, kFar)) polygons.push_back(std::move(face));
  return polygons;
}

// ---- Polygon measures ----

inline glm::dvec3 twice_area(const std::vector<glm::dvec3>& v) {
  glm::dvec3 sum(0.0);
  for (size_t i = 1; i + 1 < v.size(); ++i) sum += glm::cross(v[i] - v[0], v[i + 1] - v[0]);
  return sum;
}

inline double area(const std::vector<glm::dvec3>& v) { return 0.5 * glm::length(twice_area(v)); }

// A uniform point of a convex polygon: a fan triangle by area, then uniform in it.
inline glm::dvec3 sample_in(const std::vector<glm::dvec3>& v, Rng& rng) {
  std::vector<double> weights;
  for (size_t i = 1; i + 1 < v.size(); ++i) weights.push_back(glm::length(glm::cross(v[i] - v[0], v[i + 1] - v[0])));
  const size_t i = 1 + std::discrete_distribution<size_t>(weights.begin(), weights.end())(rng);
  double s = uniform(rng, 0.0, 1.0), t = uniform(rng, 0.0, 1.0);
  if (s + t > 1.0) std::tie(s, t) = std::pair(1.0 - s, 1.0 - t);
  return v[0] + s * (v[i] - v[0]) + t * (v[i + 1] - v[0]);
}

// Van Oosterom and Strackee's solid angle of a triangle seen from the origin, unsigned.
inline double solid_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double det = std::abs(glm::dot(a, glm::cross(b, c)));
  return 2.0 * std::atan2(det, la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la);
}

// How much of the light's influence a polygon covers: a point light's solid angle, a
// directional light's area across D.
inline double coverage(const Light& light, const std::vector<glm::dvec3>& v) {
  if (light.type == LightType::directional) return 0.5 * std::abs(glm::dot(twice_area(v), travel(light)));
  const glm::dvec3 l(light.position);
  double sum = 0.0;
  for (size_t i = 1; i + 1 < v.size(); ++i) sum += solid_angle(v[0] - l, v[i] - l, v[i + 1] - l);
  return sum;
}

// The polygon's perimeter as the light sees it: in radians from a point light, in metres
// across D.
inline double seen_perimeter(const Light& light, const std::vector<glm::dvec3>& v) {
  double sum = 0.0;
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 a = v[i] - glm::dvec3(light.position), b = v[(i + 1) % v.size()] - glm::dvec3(light.position);
    if (light.type == LightType::directional) {
      const glm::dvec3 d = travel(light);
      sum += glm::length((a - glm::dot(a, d) * d) - (b - glm::dot(b, d) * d));
    } else {
      sum += std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
    }
  }
  return sum;
}

// Sutherland–Hodgman: the part of a convex polygon where n·(x − o) ≥ 0.
inline std::vector<glm::dvec3> keep_front(const std::vector<glm::dvec3>& v, const glm::dvec3& n, const glm::dvec3& o) {
  std::vector<glm::dvec3> out;
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 &a = v[i], &b = v[(i + 1) % v.size()];
    const double da = glm::dot(n, a - o), db = glm::dot(n, b - o);
    if (da >= 0.0) out.push_back(a);
    if (da * db < 0.0) out.push_back(a + da / (da - db) * (b - a));
  }
  return out;
}

// The part of a polygon in the beam of a convex face: inside the planes through L (along D)
// and each of the face's edges.
inline std::vector<glm::dvec3> clip_to_beam(std::vector<glm::dvec3> v, const std::vector<glm::dvec3>& face, const Light& light) {
  glm::dvec3 centre(0.0);
  for (const glm::dvec3& x : face) centre += x / static_cast<double>(face.size());
  for (size_t i = 0; i < face.size() && !v.empty(); ++i) {
    const glm::dvec3 &a = face[i], &b = face[(i + 1) % face.size()];
    glm::dvec3 n = glm::cross(light.type == LightType::directional ? travel(light) : a - glm::dvec3(light.position), b - a);
    v = keep_front(v, glm::dot(n, centre - a) < 0.0 ? -n : n, a);
  }
  return v;
}

// Where the ray origin + t·dir, t > 0, meets a convex polygon, and how far inside it
// (negative: outside); nothing when the ray misses its plane or the polygon has no area.
struct Crossing {
  double t;
  double inside;
};
inline std::optional<Crossing> crossing(const std::vector<glm::dvec3>& v, const glm::dvec3& origin, const glm::dvec3& dir) {
  const glm::dvec3 normal = twice_area(v);
  if (glm::length(normal) == 0.0) return std::nullopt;
  const glm::dvec3 n = glm::normalize(normal);
  const double t = glm::dot(n, v[0] - origin) / glm::dot(n, dir);
  if (!(t > 0.0)) return std::nullopt;
  const glm::dvec3 x = origin + t * dir;
  double inside = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < v.size(); ++i) {
    const glm::dvec3 edge = v[(i + 1) % v.size()] - v[i];
    if (glm::length(edge) > 0.0) inside = std::min(inside, glm::dot(glm::normalize(glm::cross(n, edge)), x - v[i]));
  }
  return Crossing{t, inside};
}

// ---- Classification against Embree ----

struct Tally {
  int points = 0;
  int skipped = 0;   // in the ε band by Truth::robust
  int boundary = 0;  // outside the band, the tree answered boundary
  int wrong = 0;     // outside the band, the tree answered lit or shadowed against Embree
};

inline Tally classify_against_embree(const BeamTree& tree, const Light& light, const std::vector<BeamPolygon>& scene,
                                     double epsilon, int points, Rng& rng) {
  const Truth truth(light, scene, epsilon);
  Tally tally;
  for (int k = 0; k < points; ++k) {
    const glm::dvec3 p = sample_point(light, rng);
    ++tally.points;
    const std::optional<bool> lit = truth.robust(p);
    if (!lit) {
      ++tally.skipped;
      continue;
    }
    const Side side = tree.classify(p);
    tally.boundary += side == Side::boundary;
    tally.wrong += side != Side::boundary && (side == Side::lit) != *lit;
  }
  return tally;
}

inline Tally classify_against_embree(const Light& light, const std::vector<BeamPolygon>& scene, int points, Rng& rng) {
  const double epsilon = beam_epsilon(light_origin(light), scene);
  return classify_against_embree(BeamTree(light_origin(light), scene, epsilon), light, scene, epsilon, points, rng);
}

}  // namespace airlight::geometry::testing
