#include "methods/beam_volumes/lit_pyramids.hpp"

#include "geometry/influence_backplate.hpp"
#include "methods/beam_volumes/pyramid_sides.hpp"
#include "methods/kit/frame/model_of.hpp"
#include "methods/kit/frame/view_reach.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

namespace airlight::methods {
namespace {

// Whether x lies inside the pyramid from the light to `base` (the prism toward
// a directional light): on the light's side of the base's plane and inside
// every side's. The beam tree cannot say it for the eye: outside the influence
// volume its beams meet no polygon and it answers lit.
bool inside_pyramid(const geometry::BeamPolygon& base, const Light& light, const glm::dvec3& x) {
  const bool directional = light.type == LightType::directional;
  const glm::dvec3 l(light.position), d(light.direction);
  const std::vector<glm::dvec3>& v = base.vertices;
  glm::dvec3 normal = glm::cross(v[1] - v[0], v[2] - v[0]);
  const double winding = glm::dot(normal, directional ? d : v[0] - l) < 0.0 ? -1.0 : 1.0;  // away from the light
  if (winding * glm::dot(normal, x - v[0]) >= 0.0) return false;
  for (size_t k = 0; k < v.size(); ++k) {
    const glm::dvec3 a = v[k], b = v[(k + 1) % v.size()];
    const glm::dvec3 side = directional ? glm::cross(b - a, -d) : glm::cross(b - a, l - a);
    if (winding * glm::dot(side, x - a) < 0.0) return false;
  }
  return true;
}

// How far from a point light its casters reach (1 when there are none).
double caster_reach(const std::vector<geometry::BeamPolygon>& polygons, const Light& light) {
  double reach = 1.0;
  for (const geometry::BeamPolygon& p : polygons)
    for (const glm::dvec3& v : p.vertices) reach = std::max(reach, glm::distance(v, glm::dvec3(light.position)));
  return reach;
}

}  // namespace

void LitPyramids::prepare_casters(const Scene& scene, const std::vector<int>& casters) {
  casters_.clear();
  for (const int m : casters) casters_.push_back({m, scene.meshes[m].positions, scene.meshes[m].triangles});
}

std::vector<geometry::BeamPolygon> LitPyramids::world_polygons(const FrameInputs& inputs) const {
  std::vector<geometry::BeamPolygon> polygons;
  for (const Caster& caster : casters_) {
    const glm::dmat4 m = glm::dmat4(kit::model_of(inputs.transforms, caster.mesh));
    for (const glm::uvec3& t : caster.triangles) {
      geometry::BeamPolygon p;
      p.source = caster.mesh;
      for (int k = 0; k < 3; ++k) p.vertices.push_back(glm::dvec3(m * glm::dvec4(glm::dvec3(caster.positions[t[k]]), 1.0)));
      polygons.push_back(std::move(p));
    }
  }
  return polygons;
}

// A face of the lit region's boundary, its plane oriented out of the region (a,
// b, c counter-clockwise seen from outside): crossing it inward lowers the
// light's count by `weight`, so that inside a pyramid the count is 0 (lit).
void LitPyramids::add_face(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, int index, int weight) {
  triangles_.push_back(
      {{glm::vec4(a), glm::vec4(b), glm::vec4(c)}, kit::counted_plane(a, b, c), glm::ivec4(index, weight, 0, 0)});
}

// The pyramids from the light to the conforming visible set (Nilsson §3.2),
// or the prisms from it back toward a directional light, to infinity (w = 0):
// each base, wound to face out of its pyramid, and the sides that no neighbour
// shares (a shared side appears once in each direction and cancels), summed
// plane by plane (pyramid_sides.hpp).
void LitPyramids::add_pyramids(const geometry::ConformingSet& set, const Light& light, int index, double reach,
                               double epsilon) {
  const bool directional = light.type == LightType::directional;
  const glm::dvec4 apex = directional ? glm::dvec4(-glm::dvec3(light.direction), 0.0) : glm::dvec4(glm::dvec3(light.position), 1.0);
  std::vector<std::vector<int>> loops;
  // The directed edges of the bases wound away from the light, sorted: an
  // edge's count is the length of its run (a map of counts allocated a node
  // per edge, a large part of the build on toth_hall: docs/decisions.md).
  std::vector<std::uint64_t> edges;
  const auto key = [](int a, int b) { return std::uint64_t(std::uint32_t(a)) << 32 | std::uint32_t(b); };
  std::vector<std::vector<int>> conformed(set.size());  // queries of the set alone: on every core
  tbb::parallel_for(size_t{0}, set.size(), [&](size_t k) { conformed[k] = set.conforming(k); });
  for (size_t k = 0; k < set.size(); ++k) {
    std::vector<int> loop = std::move(conformed[k]);
    if (loop.size() < 3) continue;
    const glm::dvec3 v0 = set.vertex(loop[0]);
    glm::dvec3 normal(0.0);  // Newell's: robust with the collinear vertices the splits insert
    for (size_t e = 0; e < loop.size(); ++e) normal += glm::cross(set.vertex(loop[e]) - v0, set.vertex(loop[(e + 1) % loop.size()]) - v0);
    const glm::dvec3 away = directional ? glm::dvec3(light.direction) : v0 - glm::dvec3(light.position);
    if (glm::dot(normal, away) < 0.0) std::reverse(loop.begin(), loop.end());
    for (size_t e = 0; e < loop.size(); ++e) edges.push_back(key(loop[e], loop[(e + 1) % loop.size()]));
    loops.push_back(std::move(loop));
  }
  std::sort(edges.begin(), edges.end());
  const auto count = [&](int a, int b) {
    const auto run = std::equal_range(edges.begin(), edges.end(), key(a, b));
    return run.second - run.first;
  };
  const auto at = [&](int id) { return glm::dvec4(set.vertex(id), 1.0); };
  std::vector<PyramidSide> sides;
  for (const std::vector<int>& loop : loops) {
    // The base as a fan over its corners alone: the vertices the splits
    // inserted are collinear, and their slivers' planes would be noise.
    std::vector<int> corners;
    for (size_t e = 0; e < loop.size(); ++e)
      if (!set.collinear(loop[(e + loop.size() - 1) % loop.size()], loop[e], loop[(e + 1) % loop.size()]))
        corners.push_back(loop[e]);
    for (size_t k = 1; k + 1 < corners.size(); ++k)
      add_face(at(corners[0]), at(corners[k]), at(corners[k + 1]), index, 1);
    for (size_t e = 0; e < loop.size(); ++e) {
      const int a = loop[e], b = loop[(e + 1) % loop.size()];
      // Cancelled here where exactly two pyramids share the side (pieces that
      // overlap by ε as seen from the light can meet an edge more often); the
      // rest are summed plane by plane.
      if (count(b, a) != 1 || count(a, b) != 1) sides.push_back({a, b});
    }
  }
  for (const WeightedTriangle& t : summed_sides(set, sides, apex, reach, epsilon))
    add_face(t.corners[0], t.corners[1], t.corners[2], index, t.weight);
}

void LitPyramids::add_triangles(const FrameInputs& inputs) {
  eye_ = {std::vector<int>(inputs.lights.size(), 1), {}};
  nodes_ = visible_ = 0;
  const std::vector<geometry::BeamPolygon> polygons = world_polygons(inputs);
  for (size_t i = 0; i < inputs.lights.size(); ++i) {
    const Light& light = inputs.lights[i];
    std::vector<geometry::BeamPolygon> scene = polygons;
    const auto backplate = geometry::influence_backplate(light, kit::beyond_view(inputs, glm::dvec3(light.position)));
    scene.insert(scene.end(), backplate.begin(), backplate.end());
    const geometry::LightOrigin origin = geometry::light_origin(light);
    const double epsilon = geometry::beam_epsilon(origin, polygons);
    const geometry::BeamTree tree(origin, scene, epsilon);
    nodes_ += tree.node_count();
    visible_ += static_cast<int>(tree.visible_set().size());
    const size_t first = triangles_.size();
    add_pyramids(geometry::ConformingSet(tree.visible_set(), epsilon), light, static_cast<int>(i),
                 caster_reach(polygons, light), epsilon);
    const glm::dvec3 eye(inputs.camera.position);
    glm::dvec3 beside = eye;
    const std::vector<kit::EyePlane> at_eye = kit::take_planes_at_eye(
        triangles_, first, static_cast<int>(i), inputs.lights[i], eye, kit::max_eye_planes - eye_.planes.size(), beside);
    eye_.planes.insert(eye_.planes.end(), at_eye.begin(), at_eye.end());
    for (const geometry::BeamPolygon& p : tree.visible_set())
      if (inside_pyramid(p, light, beside)) eye_.counts[i] = 0;
  }
}

std::vector<std::pair<std::string, double>> LitPyramids::stats() const {
  return {{"beam_tree_nodes", static_cast<double>(nodes_)},
          {"visible_polygons", static_cast<double>(visible_)},
          {"pyramid_faces", static_cast<double>(triangles_.size())},
          {"build_s", build_s_}};
}

}  // namespace airlight::methods
