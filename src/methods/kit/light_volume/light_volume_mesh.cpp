#include "methods/kit/light_volume/light_volume_mesh.hpp"

#include "core/listed.hpp"
#include "core/warning.hpp"
#include "geometry/camera.hpp"
#include "gpu/program.hpp"
#include "methods/kit/frame/view_reach.hpp"
#include "methods/kit/method/memory_needs.hpp"
#include "methods/kit/frame/shadows/shadow_projection.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cstring>
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

enum Pass { cells_pass, grid_vertices_pass, extra_vertices_pass, grid_triangles_pass, extra_triangles_pass, eye_pass, seams_pass };

// The first `count` values of "#define NAME int[](a, b, …)" in the frame's defines.
std::vector<int> defined_ints(const std::string& defines, const std::string& name, int count) {
  const std::string key = "#define " + name + " int[](";
  const size_t at = defines.find(key);
  if (at == std::string::npos) throw Failure("light volume mesh: the frame's defines have no " + name);
  std::vector<int> values;
  const char* p = defines.c_str() + at + key.size();
  while (static_cast<int>(values.size()) < count) {
    char* end = nullptr;
    values.push_back(static_cast<int>(std::strtol(p, &end, 10)));
    if (end == p) throw Failure("light volume mesh: cannot read " + name + " from the frame's defines");
    p = end;
    while (*p == ',' || *p == ' ') ++p;
  }
  return values;
}

// The width of the texture bound to `unit` as `target` (its query enum).
int bound_texture_size(GLuint unit, GLenum binding_query) {
  GLint active = 0, id = 0, width = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  glActiveTexture(GL_TEXTURE0 + unit);
  glGetIntegerv(binding_query, &id);
  glActiveTexture(static_cast<GLenum>(active));
  if (id) glGetTextureLevelParameteriv(static_cast<GLuint>(id), 0, GL_TEXTURE_WIDTH, &width);
  return width;
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

void LightVolumeMesh::prepare() {
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
    extras_ = gpu::make_buffer(static_cast<size_t>(4 * grid + 8) * sizeof(glm::vec4), nullptr);
  }
  if (depth_ != Depth::texel && !cell_low_) {
    cell_low_ = gpu::make_texture(GL_TEXTURE_2D_ARRAY, GL_R32UI, grid, grid, vertex_layers_);
    cell_high_ = gpu::make_texture(GL_TEXTURE_2D_ARRAY, GL_R32UI, grid, grid, vertex_layers_);
  }
  triangles_.reserve(static_cast<size_t>(triangles));
  eye_counts_.reserve(static_cast<size_t>(lights));
}

void LightVolumeMesh::build(const SceneFrame& frame) {
  gpu::ScopedPass pass(timer_.emplace(), "volume");
  frame.bind();
  const int lights = frame.light_count();
  const std::vector<int> types = defined_ints(frame.defines(), "LIGHT_TYPES", lights);
  const std::vector<int> shadows = defined_ints(frame.defines(), "LIGHT_SHADOWS", lights);
  ranges_.assign(static_cast<size_t>(lights), {});
  bool maps = false, cubes = false;
  for (int i = 0; i < lights; ++i) {
    Kind& kind = ranges_[static_cast<size_t>(i)].kind;
    if (shadows[i] == shadow_cube) kind = Kind::cube;
    else if (shadows[i] == shadow_map)
      kind = types[i] == static_cast<int>(LightType::directional) ? Kind::directional : Kind::spot;
    maps = maps || kind == Kind::spot || kind == Kind::directional;
    cubes = cubes || kind == Kind::cube;
  }
  map_size_ = std::max(maps ? bound_texture_size(binding::shadow_maps, GL_TEXTURE_BINDING_2D_ARRAY) : 0,
                       cubes ? bound_texture_size(binding::shadow_cubes, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY) : 0);
  grid_ = std::max(1, std::min(resolution_, map_size_));
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
  // Lights without a map: inside their (unbounded) lit volume, outside any shell.
  const GLint no_map = depth_ == Depth::shell ? 1 : 0;
  glClearNamedBufferData(eye_counts_.id(), GL_R32I, GL_RED_INTEGER, GL_INT, &no_map);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, extras_binding, extras_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, eye_binding, eye_counts_.id());
  glBindImageTexture(vertices_unit, vertices_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_RGBA32F);
  if (depth_ != Depth::texel) {
    glBindImageTexture(low_unit, cell_low_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
    glBindImageTexture(high_unit, cell_high_.id(), 0, GL_TRUE, 0, GL_READ_WRITE, GL_R32UI);
  }
  for (int i = 0; i < lights; ++i)
    if (ranges_[static_cast<size_t>(i)].kind != Kind::none) build_light(i, ranges_[static_cast<size_t>(i)].kind, frame);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
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
  // Cells too wide for one invocation's loop (llvmpipe ends an invocation's
  // loops silently after 65535 iterations) are split into 64² sub-blocks.
  const int span = (s + r - 1) / r + 1, sub_blocks = (span + cell_block - 1) / cell_block;
  const bool split = sub_blocks > 1;

  const char* kinds[] = {"", "KIND_SPOT", "KIND_CUBE", "KIND_DIRECTIONAL"};
  const std::string common = binding_defines() + "#define BINDING_VOLUME_EXTRAS " + std::to_string(extras_binding) +
                             "\n#define BINDING_VOLUME_RECORDS " + std::to_string(records_binding) +
                             "\n#define BINDING_VOLUME_EYE " + std::to_string(eye_binding) + "\n#define VOLUME_KIND " +
                             kinds[static_cast<int>(kind)] + "\n#define DEPTH_MODE " +
                             std::to_string(static_cast<int>(depth_)) + "\n";
  auto use = [&](Pass pass) -> const gpu::Program& {
    // Only the cell pass depends on the split.
    std::string defines = common + "#define PASS " + std::to_string(pass) + "\n";
    if (pass == cells_pass && split) defines += "#define CELL_SPLIT\n";
    const gpu::Program& p = gpu::cached_compute_program("methods/kit/light_volume/light_volume_mesh.comp.glsl", defines);
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
  // A pass that writes `per_item` records per item from record `first`, in
  // ranges no larger than an SSBO binding may be.
  GLint align = 16;
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
  auto write_records = [&](const gpu::Program& p, GLsizei first, GLuint items, GLuint per_item) {
    const GLuint chunk = static_cast<GLuint>(max_records_) / per_item;
    for (GLuint done = 0; done < items; done += chunk) {
      const GLuint n = std::min(chunk, items - done);
      const GLintptr at = (static_cast<GLintptr>(first) + static_cast<GLintptr>(done) * per_item) * record_bytes;
      const GLintptr base = at - at % align;
      glBindBufferRange(GL_SHADER_STORAGE_BUFFER, records_binding, triangles_.id(), base,
                        at - base + static_cast<GLsizeiptr>(n) * per_item * record_bytes);
      gpu::set_uniform(p, "word_offset", static_cast<int>((at - base) / word_bytes));
      dispatch_items(p, done, n);
    }
  };
  const GLuint cells = static_cast<GLuint>(faces * r * r);
  if (depth_ != Depth::texel) {
    if (split) {  // atomics from every sub-block: start from the empty interval
      const GLuint empty_low = 0xffffffffu, empty_high = 0u;
      glClearTexImage(cell_low_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty_low);
      glClearTexImage(cell_high_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty_high);
    }
    dispatch_items(use(cells_pass), 0, cells * static_cast<GLuint>(sub_blocks * sub_blocks));
  }
  dispatch_items(use(grid_vertices_pass), 0, static_cast<GLuint>(faces * (r + 1) * (r + 1)));
  const bool shell = depth_ == Depth::shell;
  if (kind == Kind::cube && shell) dispatch_items(use(seams_pass), 0, static_cast<GLuint>(6 * 4 * r));
  const GLsizei first = ranges_[static_cast<size_t>(light)].first;
  const GLuint per_cell = shell ? 4 : 6;  // shell: two per cell and surface; texel: the top and two walls
  write_records(use(grid_triangles_pass), first, cells, per_cell);
  const GLsizei extras_first = first + static_cast<GLsizei>(per_cell * cells);
  if (shell) {
    if (kind != Kind::cube)  // the strips between the borders
      write_records(use(extra_triangles_pass), extras_first, static_cast<GLuint>(4 * r), 2);
  } else if (kind == Kind::cube) {  // the walls across the cube's edges
    write_records(use(extra_triangles_pass), extras_first, static_cast<GLuint>(6 * 4 * r), 2);
  } else {
    const bool spot = kind == Kind::spot;
    dispatch_items(use(extra_vertices_pass), 0, spot ? 1u : static_cast<GLuint>(4 * r + 8));
    write_records(use(extra_triangles_pass), extras_first,
                  spot ? static_cast<GLuint>(12 * r) : static_cast<GLuint>(20 * r + 14), 1);
  }
  dispatch_items(use(eye_pass), 0, 1);
}

std::vector<int> LightVolumeMesh::eye_counts() const {
  std::vector<int> counts(ranges_.size(), 0);
  if (!counts.empty())
    glGetNamedBufferSubData(eye_counts_.id(), 0, static_cast<GLsizeiptr>(counts.size() * sizeof(int)), counts.data());
  return counts;
}

std::vector<CountedTriangle> LightVolumeMesh::read_back() const {
  std::vector<CountedTriangle> triangles(static_cast<size_t>(triangle_count_));
  if (!triangles.empty())
    glGetNamedBufferSubData(triangles_.id(), 0, static_cast<GLsizeiptr>(triangles.size()) * record_bytes,
                            triangles.data());
  return triangles;
}

double LightVolumeMesh::seconds() const {
  if (timer_)
    for (const PassTime& t : timer_->results()) seconds_ = t.seconds;  // the build's one pass, once: results() empties the timer
  return seconds_;
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
  for (size_t i = 0; i < kinds.size(); ++i) {
    const bool directional = scene.lights[i].type == LightType::directional;
    const Kind kind = kinds[i] == shadow_cube  ? Kind::cube
                      : kinds[i] != shadow_map ? Kind::none
                      : directional            ? Kind::directional
                                               : Kind::spot;
    ++lights[static_cast<int>(kind)];
  }
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
