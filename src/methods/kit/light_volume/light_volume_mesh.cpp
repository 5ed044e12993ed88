#include "methods/kit/light_volume/light_volume_mesh.hpp"

#include "core/listed.hpp"
#include "core/warning.hpp"
#include "geometry/camera.hpp"
#include "gpu/program.hpp"
#include "methods/kit/frame/view_reach.hpp"
#include "methods/kit/method/memory_needs.hpp"
#include "methods/kit/frame/shadows/shadow_projection.hpp"

#include <algorithm>
#include <glm/geometric.hpp>
#include <string>

namespace airlight::kit {
namespace {

constexpr GLuint extras_binding = binding::first_free_storage;
constexpr GLuint records_binding = binding::first_free_storage + 1;
constexpr GLuint eye_binding = binding::first_free_storage + 2;
constexpr GLuint vertices_unit = 0, low_unit = 1, high_unit = 2;  // image units
constexpr int cell_block = 64;  // CELL_BLOCK: texels per side one invocation reduces
constexpr GLuint group_size = 64;
constexpr GLsizeiptr record_bytes = sizeof(CountedTriangle);
constexpr GLsizeiptr word_bytes = 16;  // a uvec4: records are five
static_assert(sizeof(CountedTriangle) == 5 * word_bytes, "CountedTriangle is five vec4s (lit_intervals.glsl)");

// The programs of the build, each including light_volume_mesh.glsl.
constexpr const char* cell_depths = "methods/kit/light_volume/cell_depths.comp.glsl";
constexpr const char* grid_vertices = "methods/kit/light_volume/grid_vertices.comp.glsl";
constexpr const char* seam_vertices = "methods/kit/light_volume/seam_vertices.comp.glsl";
constexpr const char* extra_vertices = "methods/kit/light_volume/extra_vertices.comp.glsl";
constexpr const char* grid_triangles = "methods/kit/light_volume/grid_triangles.comp.glsl";
constexpr const char* extra_triangles = "methods/kit/light_volume/extra_triangles.comp.glsl";
constexpr const char* eye_count = "methods/kit/light_volume/eye_count.comp.glsl";

// The mesh a light gets from its shadow map's kind (shadow_projection.hpp).
LightVolumeMesh::Kind kind_of(int shadow, LightType type) {
  using Kind = LightVolumeMesh::Kind;
  if (shadow == shadow_cube) return Kind::cube;
  if (shadow != shadow_map) return Kind::none;
  return type == LightType::directional ? Kind::directional : Kind::spot;
}

// The build's programs for a light of `kind`, in the order build_light runs them.
std::vector<const char*> build_programs(LightVolumeMesh::Kind kind, LightVolumeMesh::Depth depth) {
  const bool shell = depth == LightVolumeMesh::Depth::shell, cube = kind == LightVolumeMesh::Kind::cube;
  std::vector<const char*> programs;
  if (shell) programs.push_back(cell_depths);
  programs.push_back(grid_vertices);
  if (shell && cube) programs.push_back(seam_vertices);  // the shell's cube edges
  programs.push_back(eye_count);                          // and the light's orientation, for the triangles
  programs.push_back(grid_triangles);
  if (!shell && !cube) programs.push_back(extra_vertices);  // the apex, or the far ring, skirt and cap
  if (!(shell && cube)) programs.push_back(extra_triangles);  // a cube's shell has no border
  return programs;
}

// Cells too wide for one invocation's loop (llvmpipe ends an invocation's
// loops silently after 65535 iterations) are split into sub-blocks of
// cell_block² texels: how many per side, for a grid of r cells over a map of s texels.
int sub_blocks_of(int r, int s) {
  const int span = (s + r - 1) / r + 1;
  return (span + cell_block - 1) / cell_block;
}

GLsizei triangles_of(LightVolumeMesh::Kind kind, int r, LightVolumeMesh::Depth depth) {
  const bool shell = depth == LightVolumeMesh::Depth::shell;
  switch (kind) {
    case LightVolumeMesh::Kind::spot: return shell ? 4 * r * r + 8 * r : 6 * r * r + 12 * r;
    case LightVolumeMesh::Kind::cube: return shell ? 24 * r * r : 36 * r * r + 48 * r;
    case LightVolumeMesh::Kind::directional: return shell ? 4 * r * r + 8 * r : 6 * r * r + 20 * r + 14;
    case LightVolumeMesh::Kind::none: break;
  }
  return 0;
}

// Runs the bound program over `count` items from `first` (local_item in the shader).
void dispatch_items(const gpu::Program& program, GLuint first, GLuint count) {
  if (count == 0) return;
  gpu::set_uniform(program, "first_item", static_cast<int>(first));
  gpu::set_uniform(program, "item_count", static_cast<int>(count));
  const GLuint groups = (count + group_size - 1) / group_size;
  const GLuint x = std::min<GLuint>(groups, 65535u), y = (groups + x - 1) / x;
  glDispatchCompute(x, y, 1);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);  // the next pass reads it, or clears or rewrites what it read
}

}  // namespace

std::vector<SettingSpec> light_volume_settings(int default_resolution) {
  using T = SettingSpec::Type;
  return {{"volume_resolution", T::integer, static_cast<double>(default_resolution), 32, 4096, {},
           "cells per side of the grid each shadow map (or cube face) is turned into for the light volume mesh "
           "(Kingston §4.3.1, McCool 2000), clamped to the map's resolution with a warning: about 6R² triangles per map, 36R² per cube "
           "(light_volume's mesh; sv_march's shell 4R² and 24R²)"}};
}

LightVolumeMesh::LightVolumeMesh(int resolution, Depth depth) : resolution_(resolution), depth_(depth) {}

void LightVolumeMesh::prepare(const Scene&) {
  GLint64 block = 0;
  GLint align = 16;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
  max_records_ = static_cast<GLsizei>(std::max<GLint64>((block - align) / record_bytes, 1));
  vertex_grid_ = vertex_layers_ = 0;
  eye_counts_.release();
  triangles_.release();
  triangles_.reserve(0);  // a buffer to bind before the first build
}

void LightVolumeMesh::allocate(int grid, int layers, GLsizei triangles, int lights) {
  if (grid != vertex_grid_ || layers > vertex_layers_) {
    vertex_grid_ = grid;
    vertex_layers_ = layers;
    vertices_ = gpu::make_texture(GL_TEXTURE_2D_ARRAY, GL_RGBA32F, grid + 1, grid + 1, layers);
    cell_low_ = gpu::Texture();
    cell_high_ = gpu::Texture();
    extras_ = gpu::make_buffer(static_cast<size_t>(4 * grid + 9) * sizeof(glm::vec4), nullptr);  // ORIENTATION_SLOT last
  }
  if (depth_ != Depth::texel && !cell_low_) {
    cell_low_ = gpu::make_texture(GL_TEXTURE_2D_ARRAY, GL_R32UI, grid, grid, vertex_layers_);
    cell_high_ = gpu::make_texture(GL_TEXTURE_2D_ARRAY, GL_R32UI, grid, grid, vertex_layers_);
  }
  triangles_.reserve(static_cast<size_t>(triangles));
  eye_counts_.reserve(static_cast<size_t>(lights));
}

void LightVolumeMesh::build(const SceneFrame& frame, gpu::PassTimer& timer) {
  gpu::ScopedPass pass(timer, "volume");
  if (!timer_) timer_.emplace();
  {
    gpu::ScopedPass own(*timer_, "volume");
    build_lights(frame);
  }
  timer_->end_frame();
}

// The frame's lights' kinds, grid and triangle ranges, and the objects sized
// for them (allocate): before the build's programs are warmed, which bind them.
void LightVolumeMesh::size_for(const SceneFrame& frame) {
  const int lights = frame.light_count();
  ranges_.assign(static_cast<size_t>(lights), {});
  bool maps = false, cubes = false;
  for (int i = 0; i < lights; ++i) {
    const size_t light = static_cast<size_t>(i);
    const Kind kind = ranges_[light].kind = kind_of(frame.shadow_kinds()[light], frame.inputs().lights[light].type);
    maps = maps || kind == Kind::spot || kind == Kind::directional;
    cubes = cubes || kind == Kind::cube;
  }
  map_size_ = maps || cubes ? frame.shadow_resolution() : 0;
  grid_ = grid_for(map_size_);
  if (resolution_ > map_size_ && map_size_ > 0 && map_size_ != clamped_to_) {  // said once per map size
    clamped_to_ = map_size_;
    warn("volume_resolution", std::to_string(resolution_) + " is above the shadow maps' " + std::to_string(map_size_) +
                                  ": the grid is " + std::to_string(grid_) + ", a vertex per texel (what a map holds)");
  }
  triangle_count_ = 0;
  for (LightRange& range : ranges_) {
    range.first = triangle_count_;
    range.count = triangles_of(range.kind, grid_, depth_);
    triangle_count_ += range.count;
  }
  allocate(grid_, (cubes ? 6 : 1) * 2, triangle_count_, lights);  // shell: two surfaces; texel: steps and origins
}

void LightVolumeMesh::build_lights(const SceneFrame& frame) {
  size_for(frame);
  // Lights without a map: inside their (unbounded) lit volume, outside any shell.
  const GLint no_map = depth_ == Depth::shell ? 1 : 0;
  glClearNamedBufferData(eye_counts_.id(), GL_R32I, GL_RED_INTEGER, GL_INT, &no_map);
  for (int i = 0; i < frame.light_count(); ++i)
    if (ranges_[static_cast<size_t>(i)].kind != Kind::none) build_light(i, ranges_[static_cast<size_t>(i)].kind, frame);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  frame.bind();  // as build() says, whichever context built the lights
  bind_objects();
}

void LightVolumeMesh::bind_objects() const {
  images().bind();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, extras_binding, extras_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, eye_binding, eye_counts_.id());
}

// The build's images, by their names (for the worker's thread, LightVolumeMesh::warm).
void LightVolumeMesh::Images::bind() const {
  glBindImageTexture(vertices_unit, vertices, 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
  if (low) glBindImageTexture(low_unit, low, 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  if (high) glBindImageTexture(high_unit, high, 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
}

LightVolumeMesh::Images LightVolumeMesh::images() const {
  return {vertices_.id(), depth_ != Depth::texel ? cell_low_.id() : 0u, depth_ != Depth::texel ? cell_high_.id() : 0u};
}

// A build program's warm-up: the frame's textures and the build's images
// bound as the build binds them, and one workgroup with no items, where every
// invocation returns at once (item_count is 0 until the build sets it).
gpu::Warm LightVolumeMesh::warm(const SceneFrame& frame) const {
  return [frame = frame.bindings(), images = images()](const gpu::Program& p) {
    frame.bind();
    images.bind();
    glUseProgram(p.id());
    glDispatchCompute(1, 1, 1);
    glUseProgram(0);
  };
}

int LightVolumeMesh::grid_for(int map_size) const { return std::max(1, std::min(resolution_, map_size)); }

// What `program` is compiled with for a light of `kind`; `split`: the cells
// are reduced in sub-blocks (only the cell depths depend on it).
std::string LightVolumeMesh::defines(Kind kind, const char* program, bool split) const {
  const char* kinds[] = {"", "KIND_SPOT", "KIND_CUBE", "KIND_DIRECTIONAL"};
  std::string d = binding_defines() + "#define BINDING_VOLUME_EXTRAS " + std::to_string(extras_binding) +
                  "\n#define BINDING_VOLUME_RECORDS " + std::to_string(records_binding) +
                  "\n#define BINDING_VOLUME_EYE " + std::to_string(eye_binding) + "\n#define VOLUME_KIND " +
                  kinds[static_cast<int>(kind)] + "\n#define DEPTH_MODE " + std::to_string(static_cast<int>(depth_)) +
                  "\n";
  return program == cell_depths && split ? d + "#define CELL_SPLIT\n" : d;
}

// Each kind's programs linked and warmed together, the last light's kind
// first: the build runs from the first light, and takes back the kinds the
// worker has not begun when it reaches them (gpu::cached_program), so that
// the two meet in the middle.
void LightVolumeMesh::link_ahead(const SceneFrame& frame) {
  size_for(frame);
  std::vector<Kind> kinds;
  for (const LightRange& range : ranges_)
    if (range.kind != Kind::none && std::find(kinds.begin(), kinds.end(), range.kind) == kinds.end())
      kinds.push_back(range.kind);
  const bool split = sub_blocks_of(grid_, map_size_) > 1;
  for (auto kind = kinds.rbegin(); kind != kinds.rend(); ++kind) {
    std::vector<std::pair<std::string, std::string>> programs;
    for (const char* program : build_programs(*kind, depth_)) programs.emplace_back(program, defines(*kind, program, split));
    gpu::link_compute_ahead_together(programs, warm(frame));
  }
}

void LightVolumeMesh::build_light(int light, Kind kind, const SceneFrame& frame) {
  const int r = grid_, s = map_size_, faces = kind == Kind::cube ? 6 : 1;
  const FrameInputs& in = frame.inputs();
  const Light& l = in.lights[static_cast<size_t>(light)];
  const glm::dvec3 eye = geometry::camera_basis(in.camera).position;
  // Depths beyond every point the frame can see (beyond_view).
  double far_depth = beyond_view(in, glm::dvec3(l.position)), far_ring = far_depth;
  double cap = 0.0, visible = 2.0 * view_reach(in);
  if (kind == Kind::directional) {
    const double depth = glm::dot(eye, glm::dvec3(glm::normalize(l.direction)));
    far_depth = depth + visible;
    far_ring = far_depth + 1e-3 * visible;
    cap = depth - visible;
  }
  const int sub_blocks = sub_blocks_of(r, s);
  const bool split = sub_blocks > 1;
  const std::vector<const char*> names = build_programs(kind, depth_);
  std::vector<const gpu::Program*> programs;  // asked for here, on the drawing thread
  for (const char* name : names) programs.push_back(&gpu::cached_compute_program(name, defines(kind, name, split)));
  const auto runs = [&](const char* program) { return std::find(names.begin(), names.end(), program) != names.end(); };
  auto use = [&](const char* program) -> const gpu::Program& {
    const gpu::Program& p = *programs[static_cast<size_t>(std::find(names.begin(), names.end(), program) - names.begin())];
    glUseProgram(p.id());
    gpu::set_uniform(p, "light_index", light);
    gpu::set_uniform(p, "grid", r);
    gpu::set_uniform(p, "map_size", s);
    gpu::set_uniform(p, "far_depth", static_cast<float>(far_depth));
    gpu::set_uniform(p, "far_ring_depth", static_cast<float>(far_ring));
    gpu::set_uniform(p, "cap_depth", static_cast<float>(cap));
    gpu::set_uniform(p, "visible_range", static_cast<float>(visible));
    gpu::set_uniform(p, "sub_blocks", sub_blocks);
    gpu::set_uniform(p, "word_offset", 0);
    return p;
  };
  // A pass that writes a record per item from record `first`, in ranges no
  // larger than an SSBO binding may be.
  GLint align = 16;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
  auto write_records = [&](const gpu::Program& p, GLsizei first, GLuint items) {
    const GLuint chunk = static_cast<GLuint>(max_records_);
    for (GLuint done = 0; done < items; done += chunk) {
      const GLuint n = std::min(chunk, items - done);
      const GLintptr at = (static_cast<GLintptr>(first) + static_cast<GLintptr>(done)) * record_bytes;
      const GLintptr base = at - at % align;
      glBindBufferRange(GL_SHADER_STORAGE_BUFFER, records_binding, triangles_.id(), base,
                        at - base + static_cast<GLsizeiptr>(n) * record_bytes);
      gpu::set_uniform(p, "word_offset", static_cast<int>((at - base) / word_bytes));
      dispatch_items(p, done, n);
    }
  };
  const GLuint cells = static_cast<GLuint>(faces * r * r);
  // Where the kind's programs were warmed, all in one place (link_ahead).
  frame.run_where_warmed(*programs.front(), [&] {
    bind_objects();
    if (runs(cell_depths)) {
      if (split) {  // atomics from every sub-block: start from the empty interval
        const GLuint empty_low = 0xffffffffu, empty_high = 0u;
        glClearTexImage(cell_low_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty_low);
        glClearTexImage(cell_high_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty_high);
      }
      dispatch_items(use(cell_depths), 0, cells * static_cast<GLuint>(sub_blocks * sub_blocks));
    }
    dispatch_items(use(grid_vertices), 0, static_cast<GLuint>(faces * (r + 1) * (r + 1)));
    const bool shell = depth_ == Depth::shell, spot = kind == Kind::spot;
    if (runs(seam_vertices)) dispatch_items(use(seam_vertices), 0, static_cast<GLuint>(6 * 4 * r));
    dispatch_items(use(eye_count), 0, 1);
    const GLsizei first = ranges_[static_cast<size_t>(light)].first;
    const GLuint per_cell = shell ? 4 : 6;  // shell: two per cell and surface; texel: the top and two walls
    write_records(use(grid_triangles), first, per_cell * cells);
    const GLsizei extras_first = first + static_cast<GLsizei>(per_cell * cells);
    if (runs(extra_vertices)) dispatch_items(use(extra_vertices), 0, spot ? 1u : static_cast<GLuint>(4 * r + 8));
    if (runs(extra_triangles)) {
      // shell: the strips between the borders; cube: the walls across its
      // edges; spot: the sides to the apex; directional: walls, skirt and cap.
      const bool cube = kind == Kind::cube;
      const int items = shell ? 8 * r : cube ? 6 * 8 * r : spot ? 12 * r : 20 * r + 14;
      write_records(use(extra_triangles), extras_first, static_cast<GLuint>(items));
    }
  });
}

EyeCounts LightVolumeMesh::eye_counts() const {
  std::vector<int> counts(ranges_.size(), 0);
  if (!counts.empty())
    glGetNamedBufferSubData(eye_counts_.id(), 0, static_cast<GLsizeiptr>(counts.size() * sizeof(int)), counts.data());
  return {counts, {}};
}

std::vector<std::pair<std::string, double>> LightVolumeMesh::stats() const {
  return {{"volume_triangles", static_cast<double>(triangle_count_)}, {"volume_s", seconds()}};
}

std::vector<CountedTriangle> LightVolumeMesh::read_back() const {
  std::vector<CountedTriangle> triangles(static_cast<size_t>(triangle_count_));
  if (!triangles.empty())
    glGetNamedBufferSubData(triangles_.id(), 0, static_cast<GLsizeiptr>(triangles.size()) * record_bytes,
                            triangles.data());
  return triangles;
}

double LightVolumeMesh::seconds() const {
  const std::vector<PassTime> times = timer_ ? timer_->ready().times : std::vector<PassTime>{};
  return times.empty() ? 0.0 : times.front().seconds;  // the build's one pass
}

namespace {

// "1 cube map (6 faces × 6·2048² triangles)": a kind's lights and their meshes.
std::string meshes_text(LightVolumeMesh::Kind kind, int lights, int r, LightVolumeMesh::Depth depth) {
  using Kind = LightVolumeMesh::Kind;
  const std::string per_sheet = std::string(depth == LightVolumeMesh::Depth::shell ? "4·" : "6·") + squared(r) + " triangles";
  const std::string map = kind == Kind::cube ? "cube map" : kind == Kind::spot ? "spot map" : "directional map";
  return counted(lights, map) + " (" + (kind == Kind::cube ? "6 faces × " + per_sheet : per_sheet + " and the sides") +
         (lights > 1 ? " each)" : ")");
}

}  // namespace

// triangles_of for each light, in one buffer, and what allocate() gives the
// grid's vertices (and, for the shell, its cells' bounds) for the largest kind.
std::vector<MemoryNeed> light_volume_mesh_needs(const Scene& scene, const Settings& settings, LightVolumeMesh::Depth depth) {
  using Kind = LightVolumeMesh::Kind;
  const int r = std::min(settings.integer("volume_resolution"), settings.integer("shadow_resolution"));
  int lights[4] = {0, 0, 0, 0};  // by Kind
  const std::vector<int> kinds = shadow_kinds(scene);
  for (size_t i = 0; i < kinds.size(); ++i) ++lights[static_cast<int>(kind_of(kinds[i], scene.lights[i].type))];
  double triangles = 0.0;
  std::vector<std::string> meshes;
  for (const Kind kind : {Kind::cube, Kind::spot, Kind::directional}) {
    const int n = lights[static_cast<int>(kind)];
    if (n == 0) continue;
    triangles += double(n) * triangles_of(kind, r, depth);
    meshes.push_back(meshes_text(kind, n, r, depth));
  }
  if (triangles == 0.0) return {};
  const bool shell = depth == LightVolumeMesh::Depth::shell;
  const double layers = (lights[static_cast<int>(Kind::cube)] ? 6.0 : 1.0) * 2.0;  // as build() allocates
  const double grid = layers * ((r + 1.0) * (r + 1.0) * 16.0 + (shell ? 8.0 * r * r : 0.0));
  const double buffer = triangles * record_bytes;
  return {{"volume_resolution",
           std::string(shell ? "the shells of " : "the light volume meshes of ") + listed(meshes) + ", " +
               std::to_string(record_bytes) + " bytes a triangle",
           buffer + grid + triangles * sizeof(GLuint),  // and the kept indices (CountedDraw)
           buffer, layers * (r + 1.0) * (r + 1.0) * 16.0}};
}

}  // namespace airlight::kit
