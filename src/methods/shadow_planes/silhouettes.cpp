#include "methods/shadow_planes/silhouettes.hpp"

#include "geometry/camera.hpp"
#include "methods/kit/frame/model_of.hpp"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec4.hpp>

namespace airlight::methods {
void Silhouettes::prepare_casters(const Scene& scene, const std::vector<int>& casters) {
  casters_.clear();
  for (const int m : casters)
    casters_.push_back({m, geometry::build_topology(scene.meshes[m].positions, scene.meshes[m].triangles), {}});
}

void Silhouettes::move_casters(const FrameInputs& inputs) {
  for (Caster& c : casters_) {
    const glm::mat4 m = kit::model_of(inputs.transforms, c.mesh);
    c.world.resize(c.topology.positions.size());
    std::transform(c.topology.positions.begin(), c.topology.positions.end(), c.world.begin(),
                   [&m](const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); });
  }
}

// Biri §5.1.2: each plane as two triangles, the edge (a, b) and its ends
// pushed to infinity away from the light (homogeneous w = 0, as robust shadow
// volumes do), so that no far plane cuts it.
void Silhouettes::add_planes(const std::vector<geometry::ShadowPlane>& planes, const Light& light, int index) {
  const bool directional = light.type == LightType::directional;
  for (const geometry::ShadowPlane& p : planes) {
    const glm::vec4 a(p.a, 1.0f), b(p.b, 1.0f);
    const glm::vec4 a_far = directional ? glm::vec4(light.direction, 0.0f) : glm::vec4(p.a - light.position, 0.0f);
    const glm::vec4 b_far = directional ? glm::vec4(light.direction, 0.0f) : glm::vec4(p.b - light.position, 0.0f);
    // Through the edge and toward the light: counted_plane's (b − a) × (L − a)
    // is (a − L) × (b − L), and with (−D, 0) it is D × (b − a), the
    // orientation the edge's weight counts by (geometry/shadow_edges.hpp).
    const glm::dvec4 toward = directional ? glm::dvec4(-glm::dvec3(light.direction), 0.0)
                                          : glm::dvec4(glm::dvec3(light.position), 1.0);
    const glm::vec4 plane = kit::counted_plane(glm::dvec4(a), glm::dvec4(b), toward);
    const glm::ivec4 light_weight(index, p.weight, 0, 0);
    triangles_.push_back({{a, b, b_far}, plane, light_weight});
    triangles_.push_back({{a, b_far, a_far}, plane, light_weight});
  }
}

// The count changes by ±1 where a path crosses a caster's triangle
// (geometry/shadow_edges.hpp); a view ray, which ends at the first surface at
// or past the near plane, crosses triangles only nearer than that: where the
// near plane cuts a caster, or the eye is inside one (random scene 27: the eye
// in a box, its count 1, no plane to bring it to 0 outside the box, whose near
// wall the near plane clipped — every pixel black). Those triangles are
// counted as the planes are: +1 crossing away from the light. Only triangles
// whose bounds reach the sphere about the eye that holds the near plane's
// rectangle can be crossed so; most frames have none.
void Silhouettes::add_caps(const Caster& caster, const glm::dvec3& eye, double reach,
                           const geometry::LightOrigin& light, int index) {
  for (const glm::uvec3& t : caster.topology.triangles) {
    const glm::dvec3 a(caster.world[t.x]), b(caster.world[t.y]), c(caster.world[t.z]);
    const glm::dvec3 nearest = glm::clamp(eye, glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
    if (glm::distance(nearest, eye) > reach) continue;
    glm::dvec3 n = glm::cross(b - a, c - a);
    const glm::dvec3 away = light.directional ? glm::dvec3(light.direction) : a - glm::dvec3(light.position);
    if (glm::dot(n, away) < 0.0) n = -n;
    const double length = glm::length(n);
    if (!(length > 0.0)) continue;
    n /= length;
    const glm::vec4 plane(glm::vec3(n), static_cast<float>(glm::dot(n, a)));
    triangles_.push_back({{glm::vec4(glm::vec3(a), 1.0f), glm::vec4(glm::vec3(b), 1.0f), glm::vec4(glm::vec3(c), 1.0f)},
                          plane, glm::ivec4(index, 1, 0, 0)});
  }
}

// The count at p (the eye, or beside it off the planes through it) over every caster.
int Silhouettes::count_at(const geometry::LightOrigin& light, const glm::vec3& p) const {
  int count = 0;
  for (const Caster& c : casters_) count += geometry::shadow_count(c.topology, c.world, light, p);
  return count;
}

// How far from the eye the near plane's rectangle reaches (add_caps), a
// thousandth more for rounding.
namespace {
double near_reach(const FrameInputs& inputs) {
  const double aspect = double(inputs.width) / double(std::max(inputs.height, 1));
  return geometry::corner_distance(inputs.camera, aspect, inputs.camera.near) * 1.001;
}
}  // namespace

// Per caster its welded positions moved by the frame's transform, then per
// light the planes of every caster and the eye's count (Biri §5.1.1: the
// silhouettes depend on the light and the caster, so both are rebuilt every frame).
void Silhouettes::add_triangles(const FrameInputs& inputs) {
  move_casters(inputs);
  eye_ = {std::vector<int>(inputs.lights.size(), 0), {}};
  plane_count_ = silhouette_edges_ = boundary_edges_ = loops_ = 0;
  const glm::dvec3 eye(inputs.camera.position);
  const double reach = near_reach(inputs);
  for (size_t i = 0; i < inputs.lights.size(); ++i) {
    const geometry::LightOrigin light = geometry::light_origin(inputs.lights[i]);
    const size_t first = triangles_.size();
    planes_.clear();
    for (const Caster& c : casters_) {
      const geometry::ShadowPlaneStats s = geometry::append_shadow_planes(c.topology, c.world, light, planes_);
      silhouette_edges_ += s.silhouette_edges;
      boundary_edges_ += s.boundary_edges;
      add_caps(c, eye, reach, light, static_cast<int>(i));
    }
    plane_count_ += static_cast<int>(planes_.size());
    add_planes(planes_, inputs.lights[i], static_cast<int>(i));
    glm::dvec3 beside = eye;
    const std::vector<kit::EyePlane> at_eye = kit::take_planes_at_eye(
        triangles_, first, static_cast<int>(i), inputs.lights[i], eye, kit::max_eye_planes - eye_.planes.size(), beside);
    eye_.planes.insert(eye_.planes.end(), at_eye.begin(), at_eye.end());
    eye_.counts[i] = count_at(light, glm::vec3(beside));
  }
}

void Silhouettes::build(const kit::SceneFrame& frame, gpu::PassTimer& timer) {
  CasterCrossings::build(frame, timer);
  for (const Light& light : frame.inputs().lights)  // for the report, outside build_s: it allocates
    for (const Caster& c : casters_) loops_ += geometry::shadow_plane_loops(c.topology, c.world, geometry::light_origin(light));
}

std::vector<std::pair<std::string, double>> Silhouettes::stats() const {
  double triangles = 0.0;
  for (const Caster& c : casters_) triangles += static_cast<double>(c.topology.triangles.size());
  std::vector<std::pair<std::string, double>> s{{"caster_triangles", triangles},
                                                {"planes", static_cast<double>(plane_count_)},
                                                {"silhouette_edges", static_cast<double>(silhouette_edges_)},
                                                {"boundary_edges", static_cast<double>(boundary_edges_)},
                                                {"silhouette_loops", static_cast<double>(loops_)},
                                                {"build_s", build_s_}};
  for (const Caster& c : casters_)
    s.emplace_back("caster" + std::to_string(c.mesh) + (c.topology.closed ? "_silhouettes" : "_triangle_volumes"), 1.0);
  return s;
}

}  // namespace airlight::methods
