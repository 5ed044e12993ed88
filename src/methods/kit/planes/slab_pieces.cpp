#include "methods/kit/planes/slab_pieces.hpp"

#include "geometry/conforming_set.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/ext/scalar_constants.hpp>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <map>
#include <tbb/parallel_for.h>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace airlight::kit {
namespace {

// The box moved by an object → world transform: a rigid or scaled transform keeps it a box;
// a sheared one makes it a parallelepiped, whose faces box_faces still builds from the
// transformed half-axes.
OrientedBox moved(const OrientedBox& box, const glm::mat4& m) {
  OrientedBox out;
  out.center = glm::vec3(m * glm::vec4(box.center, 1.0f));
  for (int i = 0; i < 3; ++i) {
    const glm::vec3 axis = glm::mat3(m) * box.axes[i];
    const float length = glm::length(axis);
    out.axes[i] = axis / length;
    out.half[i] = box.half[i] * length;
  }
  return out;
}

// The frustum's cross-section at view depth z, 1% wider than the image so that
// its edge pixels are covered whatever the rounding (the viewport crops the rest).
geometry::BeamPolygon cross_section(const geometry::CameraBasis& c, double aspect, double z) {
  const double y = 1.01 * c.tan_half_fov_y * z, x = aspect * y;
  const glm::dvec3 m = c.position + z * c.forward;
  return {{m - x * c.right - y * c.up, m + x * c.right - y * c.up, m + x * c.right + y * c.up,
           m - x * c.right + y * c.up},
          -1};
}

// A plane's pieces of one region as loops of the conforming set's vertices,
// counter-clockwise as the eye sees them, neighbours merged while their union
// stays convex. The beam trees cut a plane along every splitting plane that
// crosses it, most of them between pieces of the same region; each edge costs
// the rasterizer partly covered pixel quads on both sides (llvmpipe counts
// them as invocations), which merging saves.
class RegionLoops {
public:
  RegionLoops(const geometry::ConformingSet& set, const geometry::CameraBasis& camera) : set_(set), camera_(camera) {}

  std::vector<std::vector<int>> merged(size_t first, size_t last) const {
    std::vector<std::vector<int>> loops;
    for (size_t p = first; p < last; ++p) {
      std::vector<int> loop = set_.conforming(p);
      if (loop.size() < 3) continue;
      if (area(loop) < 0.0) std::reverse(loop.begin(), loop.end());
      loops.push_back(std::move(loop));
    }
    std::map<std::pair<int, int>, size_t> owner;  // directed edge → its loop
    for (size_t i = 0; i < loops.size(); ++i) own(loops, i, owner);
    for (size_t i = 0; i < loops.size(); ++i)
      for (size_t e = 0; e < loops[i].size(); ++e) {
        const int a = loops[i][e], b = loops[i][(e + 1) % loops[i].size()];
        const auto other = owner.find({b, a});
        if (other == owner.end() || other->second == i || loops[other->second].empty()) continue;
        std::vector<int> joined = splice(loops[i], loops[other->second], a, b);
        if (!convex(joined)) continue;
        loops[i] = std::move(joined);
        loops[other->second].clear();
        own(loops, i, owner);
        e = size_t(-1);  // scan the merged loop again from its start
      }
    std::erase_if(loops, [](const std::vector<int>& loop) { return loop.empty(); });
    return loops;
  }

private:
  glm::dvec2 at(int id) const {
    const glm::dvec3 d = set_.vertex(id) - camera_.position;
    return {glm::dot(d, camera_.right), glm::dot(d, camera_.up)};
  }
  static double cross(const glm::dvec2& u, const glm::dvec2& v) { return u.x * v.y - u.y * v.x; }
  double area(const std::vector<int>& loop) const {
    double twice = 0.0;
    for (size_t k = 0; k < loop.size(); ++k) twice += cross(at(loop[k]), at(loop[(k + 1) % loop.size()]));
    return twice;
  }
  static void own(const std::vector<std::vector<int>>& loops, size_t i, std::map<std::pair<int, int>, size_t>& owner) {
    for (size_t e = 0; e < loops[i].size(); ++e) owner[{loops[i][e], loops[i][(e + 1) % loops[i].size()]}] = i;
  }
  // Loop p (edge a → b) and loop q (edge b → a) joined across that edge, with
  // the spikes left where they shared more of it (… x, y, x …) removed.
  static std::vector<int> splice(const std::vector<int>& p, const std::vector<int>& q, int a, int b) {
    std::vector<int> out;
    const size_t pb = std::find(p.begin(), p.end(), b) - p.begin();
    for (size_t k = 0; k < p.size(); ++k) out.push_back(p[(pb + k) % p.size()]);  // b … a
    const size_t qa = std::find(q.begin(), q.end(), a) - q.begin();
    for (size_t k = 1; k + 1 < q.size(); ++k) out.push_back(q[(qa + k) % q.size()]);  // after a, before b
    for (bool spiked = true; spiked && out.size() >= 3;) {
      spiked = false;
      for (size_t k = 0; k < out.size() && out.size() >= 3; ++k) {
        const size_t before = (k + out.size() - 1) % out.size(), after = (k + 1) % out.size();
        if (out[before] != out[after]) continue;
        out.erase(out.begin() + static_cast<long>(std::max(k, after)));
        out.erase(out.begin() + static_cast<long>(std::min(k, after)));
        spiked = true;
      }
    }
    return out;
  }
  // Simple and convex, collinear runs allowed (the inserted vertices).
  bool convex(const std::vector<int>& loop) const {
    if (loop.size() < 3) return false;
    std::vector<int> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return false;
    double turned = 0.0;
    for (size_t k = 0; k < loop.size(); ++k) {
      const glm::dvec2 a = at(loop[k]), b = at(loop[(k + 1) % loop.size()]), c = at(loop[(k + 2) % loop.size()]);
      const glm::dvec2 u = b - a, v = c - b;
      if (cross(u, v) < -1e-9 * glm::length(u) * glm::length(v)) return false;
      turned += std::atan2(cross(u, v), glm::dot(u, v));
    }
    return turned < 2.0 * glm::pi<double>() + 1e-6;  // once around, not twice
  }

  const geometry::ConformingSet& set_;
  const geometry::CameraBasis& camera_;
};

// A convex loop as triangles from its centroid to every segment of its
// boundary: the pieces of a plane then share their edges vertex for vertex,
// so the rasterizer covers each pixel of the plane once (along a T-junction
// llvmpipe was seen to cover pixels 0.15 px from both edges twice, and a fan
// from a corner has triangles over three collinear vertices, which float
// rounding turns into slivers of either winding; back-face culling drops
// those the pass draws).
void append_fan(const geometry::ConformingSet& set, const std::vector<int>& loop, int plane,
                std::vector<PieceVertex>& out) {
  glm::dvec3 centre(0.0);
  for (const int id : loop) centre += set.vertex(id);
  centre /= double(loop.size());
  for (size_t k = 0; k < loop.size(); ++k) {
    out.push_back({glm::vec3(centre), plane});
    out.push_back({glm::vec3(set.vertex(loop[k])), plane});
    out.push_back({glm::vec3(set.vertex(loop[(k + 1) % loop.size()])), plane});
  }
}

// One plane's triangles per region and its region polygons (before merging).
struct Slab {
  std::vector<PieceVertex> fully_lit, uncertain;
  double polygons[3] = {0.0, 0.0, 0.0};
};

// The convex polygon on the side dot(xyz, x) + w >= 0 of each half-space.
geometry::BeamPolygon clipped(geometry::BeamPolygon polygon, const std::vector<glm::vec4>& half_spaces) {
  for (const glm::vec4& h : half_spaces) {
    const glm::dvec3 n(h);
    std::vector<glm::dvec3> out;
    const std::vector<glm::dvec3>& v = polygon.vertices;
    for (size_t k = 0; k < v.size(); ++k) {
      const glm::dvec3 &a = v[k], &b = v[(k + 1) % v.size()];
      const double da = glm::dot(n, a) + h.w, db = glm::dot(n, b) + h.w;
      if (da >= 0.0) out.push_back(a);
      if ((da >= 0.0) != (db >= 0.0)) out.push_back(a + (da / (da - db)) * (b - a));
    }
    polygon.vertices = std::move(out);
  }
  return polygon;
}

// Plane k's cross-section partitioned into regions, made conforming, merged and fanned.
Slab partitioned(const geometry::LightRegions& regions, const geometry::CameraBasis& camera,
                 const geometry::BeamPolygon& section, int k) {
  Slab slab;
  if (section.vertices.size() < 3) return slab;
  std::vector<geometry::BeamPolygon> parts[3];
  regions.partition(section, parts[0], parts[1], parts[2]);
  for (int r = 0; r < 3; ++r) slab.polygons[r] = static_cast<double>(parts[r].size());
  const size_t lit = parts[0].size(), uncertain = lit + parts[1].size();
  std::vector<geometry::BeamPolygon> all = std::move(parts[0]);
  all.insert(all.end(), parts[1].begin(), parts[1].end());
  all.insert(all.end(), parts[2].begin(), parts[2].end());
  const geometry::ConformingSet set(all, regions.epsilon());
  const RegionLoops loops(set, camera);
  for (const std::vector<int>& loop : loops.merged(0, lit)) append_fan(set, loop, k, slab.fully_lit);
  for (const std::vector<int>& loop : loops.merged(lit, uncertain)) append_fan(set, loop, k, slab.uncertain);
  return slab;
}

}  // namespace

void SlabPieces::prepare(const Scene& scene) {
  volumes_.clear();
  meshes_.clear();
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    if (scene.meshes[m].casts_shadows) {
      volumes_.push_back(geometry::bounding_volumes(scene.meshes[m]));
      meshes_.push_back(static_cast<int>(m));
    }
}

void SlabPieces::reset() {
  polygons_[0] = polygons_[1] = polygons_[2] = 0.0;
  nodes_ = seconds_ = 0.0;
}

SlabPieces::Pieces SlabPieces::build(const FrameInputs& inputs, int light, int count, float dz, float margin,
                                     const std::vector<glm::vec4>& clip) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<geometry::BoundingVolumes> posed = volumes_;
  for (size_t k = 0; k < posed.size(); ++k) {
    geometry::BoundingVolumes& v = posed[k];
    if (!inputs.transforms.empty()) {  // not model_of's identity: moved() would renormalize the boxes' axes
      const glm::mat4& m = inputs.transforms[meshes_[k]];
      v.outer = moved(v.outer, m);
      if (v.inner) v.inner = moved(*v.inner, m);
    }
    v.outer.half += margin;
    if (v.inner) v.inner->half -= margin;
    if (v.inner && std::min({v.inner->half.x, v.inner->half.y, v.inner->half.z}) <= 0.0f) v.inner.reset();
  }
  const geometry::LightRegions regions(geometry::light_origin(inputs.lights[light]), posed);
  nodes_ += regions.outer().node_count() + regions.inner().node_count();
  const geometry::CameraBasis camera = geometry::camera_basis(inputs.camera);
  const double aspect = double(inputs.width) / inputs.height;
  // The planes are independent: each partitioned on its own thread's turn,
  // then appended in order (the draw order, hence the blend's, stays fixed).
  std::vector<Slab> slabs(static_cast<size_t>(std::max(count, 0)));
  tbb::parallel_for(0, count, [&](int k) {
    // The slab's middle as the shader computes it: (float(k) + 0.5)·dz.
    const double z = (float(k) + 0.5f) * dz;
    slabs[k] = partitioned(regions, camera, clipped(cross_section(camera, aspect, z), clip), k);
  });
  Pieces pieces;
  for (const Slab& slab : slabs) {
    pieces.fully_lit.insert(pieces.fully_lit.end(), slab.fully_lit.begin(), slab.fully_lit.end());
    pieces.uncertain.insert(pieces.uncertain.end(), slab.uncertain.begin(), slab.uncertain.end());
    for (int r = 0; r < 3; ++r) polygons_[r] += slab.polygons[r];
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return pieces;
}

std::vector<std::pair<std::string, double>> SlabPieces::stats() const {
  return {{"fully_lit_polygons", polygons_[0]},
          {"uncertain_polygons", polygons_[1]},
          {"unlit_polygons", polygons_[2]},
          {"region_tree_nodes", nodes_},
          {"regions_s", seconds_}};
}

}  // namespace airlight::kit
