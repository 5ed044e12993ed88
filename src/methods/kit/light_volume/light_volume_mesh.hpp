#pragma once
// The light volume mesh (Kingston 2018 §4.3.1, after McCool 2000): per frame,
// on the GPU, a closed triangle mesh around each light's lit region, made from
// the light's shadow map as the frame drew it (airlight's own, or an engine's
// converted into the same textures). McCool turns a shadow map into shadow
// volumes by treating it as a terrain: its texels' depths make a surface over
// a grid, so the mesh costs O(R²) for an R² grid whatever the scene's geometry, and a
// compute shader rebuilds it every frame. Methods count a view ray's crossings
// with it (LitIntervalPass) to find the stretches where the light arrives
// instead of marching through the shadow map (Kingston §4.3.2).
//
// The grid, per light (light_volume_mesh.glsl and its programs): (R+1)² vertices over the
// map's NDC square (a cube's faces' squares), each on the ray of points that
// project there — from the light's position (spot, point) or along the
// light's travel (directional) — and placed on it at a depth (below).
// - spot, 2D map through its shadow_matrix (a perspective frustum): closed by
//   side walls from the grid's border to the light's position (the apex). The
//   volume is the frustum cut by the surface.
// - point light or wide spot (cube map): the six faces' grids, closed across
//   the seams (a cube edge's or corner's ray is the same bits on every face).
// - directional (orthographic 2D map): closed by vertical walls down to a
//   "far" ring, a skirt at that depth out to an extent that holds every point
//   the frame can see, walls up to a cap upstream of every such point, and the
//   cap. The map's own near plane and square would leave out lit fog the eye
//   sees (above the scene's bounds, or beside them, where the map says "no
//   occluder"); the skirt keeps it inside.
// Where the map holds +∞ or its clear value (no occluder), and wherever it is
// farther than that, the depth is the frame's backplate distance,
// 2·(|eye − light| + the far plane's reach) (frame/view_reach.hpp, beyond_view;
// for a directional light twice the reach past the eye's depth), beyond every
// visible point, so the mesh stays finite and closed.
//
// Two meshes (Depth):
// - texel (light_volume): the shadow map's own steps, exactly the region its
//   test calls lit. Each cell is a flat quad at its texel's stored depth (the
//   texel under the cell's centre, texel c when R = S; scene.glsl's
//   shadow_visibility compares with it, without bias), over exactly the
//   directions that read that texel, and vertical walls (on the rays between
//   cells) join it to its neighbours at theirs. A height field through the texels' depths at the cells' corners,
//   as this mesh was before, is half a texel off what the test decides: at
//   R = S it lost to raymarch at 256 steps on the same map (docs/decisions.md).
//   A wall where neighbours' depths agree has no area (no crossing); the
//   spot's and the directional map's border sides step from each border cell's
//   depth to one depth per border vertex shared by both segments there, so
//   that the edges running to the apex (or the far ring) are shared exactly. A
//   cube's walls across its edges are built by the face of the lower index.
//   Several walls meet a ray between cells at several depths: the mesh is
//   closed as a surface (its edges cancel as stretches of that ray), not edge
//   for edge, and a vertex is computed from its ray and its depth by one
//   `precise` expression wherever it is used, so shared corners are the same
//   bits.
// - shell (McCool's conservative volume, for sv_march): a height field (every
//   vertex shared by its cells; on a cube, computed by the first face that
//   holds it and copied into the others' slots), the closed surface of the
//   shell between an inner grid, each vertex at the minimum over every
//   texel of the cells that share it, and an outer grid at their maximum moved
//   on by a texel and past the chords across a cell (beyond_lit in the
//   shader), joined along the border by strips (a spot's frustum side, a
//   directional map's column side; a cube has no border). Inside the inner
//   grid every texel says lit, beyond the outer every texel says shadowed: every
//   point where the shadow map's visibility can change lies in the shell, and a
//   ray outside it has one visibility on each stretch of its own (within a
//   spot's frustum or a directional map's column). Its triangles are oriented
//   out of the shell; its eye count is 0 when the eye is inside the shell.
//
// Triangles are CountedTriangle records (lit_intervals.glsl's layout, written
// in the shader as five uvec4 words each) with weight +1 and the light's index,
// their unit normal (float, from the corners) pointing OUT of the volume
// and plane.w = n·a at the first corner, as crossings.frag.glsl expects: a view
// ray's count, started at eye_counts() (0 inside, 1 outside), is 0 exactly
// where it is inside the volume. Lights without a shadow map (SHADOW_NONE:
// nothing can occlude them) get no triangles and an eye count of 0 (texel:
// their lit region is all of space; a spot's cone is the light map's
// business), or 1 (shell: there is none).
//
// GPU limits: an SSBO binding holds at most GL_MAX_SHADER_STORAGE_BLOCK_SIZE
// bytes (128 MiB on llvmpipe, 1.68 M records); the build writes through bound
// ranges no larger than that (max_records_per_binding()), and a pass that
// reads triangles() must do the same when triangle_count() exceeds it. An R²
// spot grid is 6R² + 12R triangles (R = 1024: 505 MB; per cell its top and
// two walls, per border segment three sides), a cube 36R² + 48R (two records
// per face border segment for the walls across its edges), a directional
// light 6R² + 20R + 14; a shell 4R² + 8R, 24R² and 4R² + 8R.
#include "gpu/growing_buffer.hpp"
#include "gpu/timer.hpp"
#include "methods/kit/counting/crossing_geometry.hpp"
#include "methods/kit/frame/scene_frame.hpp"

#include <airlight/settings.hpp>
#include <optional>
#include <vector>

namespace airlight::kit {

// Settings the methods built on the mesh share: "volume_resolution" (integer,
// cells per side of each map's grid, 32 to 4096, clamped to the map's
// resolution), with the method's default.
std::vector<SettingSpec> light_volume_settings(int default_resolution);

class LightVolumeMesh final : public CrossingGeometry {
public:
  enum class Depth { texel, shell };  // which mesh (above)
  enum class Kind { none, spot, cube, directional };  // the mesh a light gets, from its shadow map

  LightVolumeMesh(int resolution, Depth depth);

  // GL objects (the scene is not needed); needs a current context.
  void prepare(const Scene& scene) override;

  // After the frame's shadow maps are drawn: every light's mesh into one
  // buffer of CountedTriangle records, lights in order, and each light's eye
  // count, timed as the pass "volume". Binds the frame (SceneFrame::bind) and
  // leaves image units 0–2 and storage bindings from
  // binding::first_free_storage bound to its own objects.
  void build(const SceneFrame& frame, gpu::PassTimer& timer) override;
  // Sizes the build's objects for the frame and starts linking and warming
  // its programs, each kind of light's together (gpu::link_compute_ahead_together).
  void link_ahead(const SceneFrame& frame) override;

  CountedTriangles triangles() const override { return {{}, &triangles_.buffer(), static_cast<size_t>(triangle_count_)}; }
  GLsizei triangle_count() const { return triangle_count_; }  // this frame's, all lights
  // Per light: 0 if the frame's eye is inside its lit volume, 1 if not (read
  // from the GPU, where the eye's cell of the mesh decides it); no planes through the eye.
  EyeCounts eye_counts() const override;
  bool has_eye_planes() const override { return false; }  // the eye's cell decides
  const gpu::Buffer& eye_count_buffer() const { return eye_counts_.buffer(); }  // the same on the GPU: one int per light
  bool uses_shadow_maps() const override { return true; }
  // volume_triangles (this frame's) and volume_s (seconds()).
  std::vector<std::pair<std::string, double>> stats() const override;
  std::vector<CountedTriangle> read_back() const;  // for tests and reports
  // The GPU time of the newest build the GPU has finished (gpu::PassTimer's,
  // read without waiting: the last build's once the GPU is idle); 0 before.
  double seconds() const;

  // Each light's records are [first, first + count) of triangles().
  struct LightRange {
    Kind kind = Kind::none;
    GLsizei first = 0, count = 0;
  };
  const std::vector<LightRange>& light_ranges() const { return ranges_; }
  int grid_resolution() const { return grid_; }  // R of the last build: the setting, clamped to the maps' size
  GLsizei max_records_per_binding() const { return max_records_; }

private:
  struct Images {  // the build's images by their names, for the worker's thread
    GLuint vertices, low, high;  // low, high: 0 for the texel mesh
    void bind() const;
  };
  Images images() const;
  void bind_objects() const;  // the images and the extras' and eye counts' buffers
  gpu::Warm warm(const SceneFrame& frame) const;
  void size_for(const SceneFrame& frame);
  void build_lights(const SceneFrame& frame);
  void build_light(int light, Kind kind, const SceneFrame& frame);
  int grid_for(int map_size) const;
  std::string defines(Kind kind, const char* program, bool split) const;
  void allocate(int grid, int layers, GLsizei triangles, int lights);

  int resolution_;
  Depth depth_;
  int grid_ = 0, map_size_ = 0;
  int clamped_to_ = 0;  // the map size the last clamping warning named
  GLsizei triangle_count_ = 0, max_records_ = 0;
  std::vector<LightRange> ranges_;
  gpu::Texture vertices_, cell_low_, cell_high_;
  int vertex_grid_ = 0, vertex_layers_ = 0;
  gpu::GrowingBuffer<CountedTriangle> triangles_;
  gpu::GrowingBuffer<GLint> eye_counts_;
  gpu::Buffer extras_;
  // Made with the first build (a timer needs the context); kept, as the
  // builds' queries are read frames later.
  std::optional<gpu::PassTimer> timer_;
};

// What the meshes of the scene's lights take at the settings' grid
// (volume_resolution, at most shadow_resolution): a MemoryNeed per map kind.
std::vector<MemoryNeed> light_volume_mesh_needs(const Scene& scene, const Settings& settings, LightVolumeMesh::Depth depth);

}  // namespace airlight::kit
