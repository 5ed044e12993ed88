#include "methods/kit/scene_frame.hpp"

#include "geometry/camera.hpp"
#include "gpu/program.hpp"
#include "optics/light.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <numbers>

namespace airlight::kit {

using namespace gpu;

namespace {

// ---- CPU mirrors of src/methods/kit/scene.glsl (vec4-aligned: std140 = std430) ----

struct FrameBlock {
  glm::mat4 view_projection;
  glm::vec4 eye, forward, right, up;
  glm::vec4 image;  // width, height, tan(fov_y / 2), aspect
  glm::vec4 clip;   // near, far, shadow bias (texels), shadow resolution
  glm::vec4 medium_sigma_s, medium_sigma_t, ambient;
  glm::vec4 light_model;  // a0, a1
  glm::ivec4 counts;      // lights, volumes, medium lobes, light model
};

struct GpuLight {
  glm::vec4 position;    // xyz: position, or a beam's origin; w: cone (rad), or beam length (0: no beam)
  glm::vec4 direction;   // w: edge (rad)
  glm::vec4 color;       // w: tan(cone) for gobo_uv, 0 when cone >= 90°
  glm::vec4 gobo_right;  // xyz: gobo / beam frame; w: beam width
  glm::vec4 gobo_up;     // xyz; w: beam height
  glm::mat4 shadow_matrix;
  glm::ivec4 meta;       // type, shadow kind, shadow slot, gobo layer
  glm::vec4 shadow;      // texel footprint = (x·distance + y) / resolution
};

struct GpuVolume {
  glm::vec4 lo, hi, sigma_s, sigma_t;
  glm::ivec4 lobe_range;
};

struct GpuLobe {
  int type;
  float g, weight, unused;
};

struct Vertex {
  glm::vec3 position, normal, albedo;
};

enum ShadowKind { shadow_none = 0, shadow_map = 1, shadow_cube = 2 };

// ---- geometry of the shadow maps ----------------------------------------------

struct Bounds {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-std::numeric_limits<double>::infinity()};
  bool empty() const { return !(lo.x <= hi.x); }
  glm::dvec3 corner(int k) const { return {(k & 1 ? hi : lo).x, (k & 2 ? hi : lo).y, (k & 4 ? hi : lo).z}; }
};

Bounds scene_bounds(const Scene& scene) {
  Bounds b;
  for (const Mesh& mesh : scene.meshes)
    for (const glm::vec3& p : mesh.positions) {
      b.lo = glm::min(b.lo, glm::dvec3(p));
      b.hi = glm::max(b.hi, glm::dvec3(p));
    }
  return b;
}

// Far plane of a light's perspective maps: beyond every occluder. The near plane
// at 1e-4 of it loses only occluders within millimetres of the light.
struct DepthRange {
  double near, far;
};
DepthRange perspective_range(const glm::dvec3& apex, const Bounds& b) {
  double far = 0.0;
  for (int k = 0; k < 8; ++k) far = std::max(far, glm::length(b.corner(k) - apex));
  far = far * 1.01 + 1e-3;
  return {far * 1e-4, far};
}

glm::dvec3 up_hint(const glm::dvec3& dir) {
  return std::abs(dir.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// World → clip of a 2D map, and its texel footprint per unit distance / constant.
struct Projection {
  glm::mat4 matrix{1.0f};
  float per_distance = 0.0f, constant = 0.0f;
};

// A spot's cone in a square perspective map of field 2·cone.
Projection spot_projection(const Light& light, const Bounds& b) {
  const glm::dvec3 apex(light.position), axis = glm::normalize(glm::dvec3(light.direction));
  const DepthRange range = perspective_range(apex, b);
  const double cone = radians(light.cone_deg);
  const glm::dmat4 view = glm::lookAt(apex, apex + axis, up_hint(axis));
  const glm::dmat4 proj = glm::perspective(2.0 * cone, 1.0, range.near, range.far);
  return {glm::mat4(proj * view), static_cast<float>(2.0 * std::tan(cone)), 0.0f};
}

// A directional light: orthographic along the light, its depth range over the
// scene's bounds (every occluder), its x/y extent over the bounds too (every
// ray through them lands inside; points outside are lit) — or, for a beam,
// over the beam's aperture: only points inside the beam are lit, so the
// texels are spent there.
Projection directional_projection(const Light& light, const Bounds& b) {
  const glm::dvec3 dir = glm::normalize(glm::dvec3(light.direction));
  glm::dvec3 eye = 0.5 * (b.lo + b.hi), up = up_hint(dir);
  if (optics::has_beam(light)) {
    glm::dvec3 right;
    optics::gobo_frame(light, right, up);  // lookAt's x is then dir × up = right: the beam's frame
    eye = glm::dvec3(light.beam->origin);
  }
  const glm::dmat4 view = glm::lookAt(eye, eye + dir, up);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 p(view * glm::dvec4(b.corner(k), 1.0));
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  if (optics::has_beam(light)) {
    const glm::dvec2 half = 0.5 * glm::dvec2(light.beam->size);
    lo = glm::dvec3(-half, lo.z);
    hi = glm::dvec3(half, hi.z);
  }
  const double margin = 1e-3 * glm::length(hi - lo) + 1e-6;
  lo -= margin;
  hi += margin;
  const glm::dmat4 proj = glm::ortho(lo.x, hi.x, lo.y, hi.y, -hi.z, -lo.z);  // view looks along -z
  return {glm::mat4(proj * view), 0.0f, static_cast<float>(std::max(hi.x - lo.x, hi.y - lo.y))};
}

// Cube faces in GL's order +x −x +y −y +z −z, with the up vectors that make a
// face rendered into a bottom-left-origin framebuffer agree with cube sampling.
std::array<glm::mat4, 6> cube_face_matrices(const glm::dvec3& apex, const Bounds& b) {
  static const std::array<std::pair<glm::dvec3, glm::dvec3>, 6> faces{{{{1, 0, 0}, {0, -1, 0}},
                                                                        {{-1, 0, 0}, {0, -1, 0}},
                                                                        {{0, 1, 0}, {0, 0, 1}},
                                                                        {{0, -1, 0}, {0, 0, -1}},
                                                                        {{0, 0, 1}, {0, -1, 0}},
                                                                        {{0, 0, -1}, {0, -1, 0}}}};
  const DepthRange range = perspective_range(apex, b);
  const glm::dmat4 proj = glm::perspective(0.5 * std::numbers::pi, 1.0, range.near, range.far);
  std::array<glm::mat4, 6> matrices;
  for (int f = 0; f < 6; ++f)
    matrices[f] = glm::mat4(proj * glm::lookAt(apex, apex + faces[f].first, faces[f].second));
  return matrices;
}

int shadow_kind(const Light& light, const Bounds& bounds) {
  if (bounds.empty()) return shadow_none;  // nothing can occlude
  if (light.type == LightType::point) return shadow_cube;
  if (light.type == LightType::spot && light.cone_deg >= wide_spot_deg) return shadow_cube;
  return shadow_map;
}

// The lights whose gobo the GPU samples: spots and beams (a gobo means nothing elsewhere).
bool has_gobo(const Light& light) {
  return (light.type == LightType::spot || optics::has_beam(light)) && light.gobo && !light.gobo->empty();
}

GpuLight light_record(const Light& light, int gobo_layer) {
  GpuLight g{};
  const double cone = radians(light.cone_deg);
  const glm::vec3 dir = glm::normalize(light.direction);
  const bool spot = light.type == LightType::spot, beam = optics::has_beam(light);
  g.position = glm::vec4(light.position, spot ? static_cast<float>(cone) : 0.0f);
  if (beam) g.position = glm::vec4(light.beam->origin, light.beam->length);
  g.direction = glm::vec4(dir, spot ? static_cast<float>(radians(light.edge_deg)) : 0.0f);
  const glm::vec3 color = light.type == LightType::directional ? light.irradiance : light.intensity;
  const bool square = spot && cone < 0.5 * std::numbers::pi;  // gobo_uv needs tan(cone) finite
  g.color = glm::vec4(color, square ? static_cast<float>(std::tan(cone)) : 0.0f);
  if (spot || beam) {
    glm::dvec3 right, up;
    optics::gobo_frame(light, right, up);
    g.gobo_right = glm::vec4(glm::vec3(right), beam ? light.beam->size.x : 0.0f);
    g.gobo_up = glm::vec4(glm::vec3(up), beam ? light.beam->size.y : 0.0f);
  }
  g.meta = glm::ivec4(static_cast<int>(light.type), shadow_none, 0, gobo_layer);
  return g;
}

// ---- textures -----------------------------------------------------------------

// The gobo resampled to width × height by optics::sample_gobo at the new texel
// centres, rows flipped (texel row 0 = the image's bottom row: t = v, light.glsl).
std::vector<glm::vec4> gobo_texels(const Image& gobo, int width, int height) {
  std::vector<glm::vec4> texels(static_cast<size_t>(width) * height);
  const bool same = gobo.width == width && gobo.height == height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::dvec2 uv((x + 0.5) / width, (y + 0.5) / height);
      const glm::vec3 c = same ? gobo.at(x, height - 1 - y) : glm::vec3(optics::sample_gobo(gobo, uv));
      texels[static_cast<size_t>(y) * width + x] = glm::vec4(c, 1.0f);
    }
  return texels;
}

Texture render_target(GLenum format, int width, int height) {
  return make_texture(GL_TEXTURE_2D, format, width, height);
}

void check_complete(const Framebuffer& fbo, const char* what) {
  const GLenum status = glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw Failure(std::string("the ") + what + " framebuffer is incomplete (status " + std::to_string(status) + ")");
}

template <typename T>
Buffer storage(const std::vector<T>& data) {
  return make_buffer(data.size() * sizeof(T), data.data());
}

}  // namespace

std::string frame_defines() {
  using namespace binding;
  const std::pair<const char*, GLuint> all[] = {
      {"FRAME_BLOCK", frame_block},   {"LIGHTS", lights},
      {"VOLUMES", volumes},           {"LOBES", lobes},
      {"FACE_NORMALS", face_normals}, {"DISTANCE", distance},
      {"NORMAL", normal},             {"GEOMETRIC_NORMAL", geometric_normal},
      {"ALBEDO", albedo},             {"GOBOS", gobos},
      {"SHADOW_MAPS", shadow_maps},   {"SHADOW_CUBES", shadow_cubes}};
  std::string text;
  for (const auto& [name, value] : all)
    text += "#define BINDING_" + std::string(name) + " " + std::to_string(value) + "\n";
  return text;
}

// ---- prepare --------------------------------------------------------------------

void SceneFrame::prepare(const Scene& scene) {
  const std::string defines = frame_defines();
  programs_.gbuffer = make_program(
      {{GL_VERTEX_SHADER, "methods/kit/gbuffer.vert.glsl"}, {GL_FRAGMENT_SHADER, "methods/kit/gbuffer.frag.glsl"}}, defines);
  programs_.background = make_program(
      {{GL_VERTEX_SHADER, "methods/kit/fullscreen.vert.glsl"}, {GL_FRAGMENT_SHADER, "methods/kit/background.frag.glsl"}}, defines);
  programs_.shadow = make_program(
      {{GL_VERTEX_SHADER, "methods/kit/shadow.vert.glsl"}, {GL_FRAGMENT_SHADER, "methods/kit/shadow.frag.glsl"}}, defines);
  programs_.surface = make_compute_program("methods/kit/surface.comp.glsl", defines);
  programs_.composite = make_compute_program("methods/kit/composite.comp.glsl", defines);
  camera_ = scene.camera;
  geometry::camera_frame(camera_);  // throws now for a degenerate camera
  light_model_ = scene.light_model;
  upload_meshes(scene);
  upload_media(scene);
  upload_gobos(scene);
  upload_lights(scene);
  frame_block_ = make_buffer(sizeof(FrameBlock), nullptr);
  gbuffer_fbo_ = make_framebuffer();
  shadow_fbo_ = make_framebuffer();
  width_ = height_ = shadow_resolution_ = 0;
}

// One vertex buffer and one index buffer for all meshes, so that one draw covers
// the scene and gl_PrimitiveID indexes the per-triangle face normals.
void SceneFrame::upload_meshes(const Scene& scene) {
  std::vector<Vertex> vertices;
  std::vector<GLuint> indices;
  std::vector<glm::vec4> face_normals;
  for (const Mesh& mesh : scene.meshes) {
    const auto base = static_cast<GLuint>(vertices.size());
    const bool normals = mesh.normals.size() == mesh.positions.size();
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      vertices.push_back({mesh.positions[v], normals ? mesh.normals[v] : glm::vec3(0.0f), mesh.albedo});
    for (const glm::uvec3& t : mesh.triangles) {
      indices.insert(indices.end(), {base + t.x, base + t.y, base + t.z});
      const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
      const glm::dvec3 n = glm::cross(b - a, c - a);
      const double length = glm::length(n);
      face_normals.emplace_back(glm::vec3(length > 0.0 ? n / length : n), 0.0f);
    }
  }
  index_count_ = static_cast<int>(indices.size());
  vertices_ = storage(vertices);
  indices_ = storage(indices);
  face_normals_ = storage(face_normals);
  vertex_array_ = make_vertex_array();
  const GLuint vao = vertex_array_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(Vertex));
  glVertexArrayElementBuffer(vao, indices_.id());
  const GLuint offsets[] = {offsetof(Vertex, position), offsetof(Vertex, normal), offsetof(Vertex, albedo)};
  for (GLuint attribute = 0; attribute < 3; ++attribute) {
    glEnableVertexArrayAttrib(vao, attribute);
    glVertexArrayAttribFormat(vao, attribute, 3, GL_FLOAT, GL_FALSE, offsets[attribute]);
    glVertexArrayAttribBinding(vao, attribute, 0);
  }
}

// The medium's lobes first (lobes[0 .. medium_lobes)), then each volume's.
void SceneFrame::upload_media(const Scene& scene) {
  std::vector<GpuLobe> lobes;
  auto append = [&](const Phase& phase) {
    const glm::ivec4 range(static_cast<int>(lobes.size()), static_cast<int>(phase.lobes.size()), 0, 0);
    for (const PhaseLobe& l : phase.lobes) lobes.push_back({static_cast<int>(l.type), l.g, l.weight, 0.0f});
    return range;
  };
  medium_lobes_ = append(scene.medium.phase).y;
  std::vector<GpuVolume> volumes;
  for (const Volume& v : scene.volumes)
    volumes.push_back({glm::vec4(v.min, 0.0f), glm::vec4(v.max, 0.0f), glm::vec4(v.sigma_s, 0.0f),
                       glm::vec4(v.sigma_t(), 0.0f), append(v.phase)});
  volume_count_ = static_cast<int>(volumes.size());
  medium_sigma_s_ = glm::vec4(scene.medium.sigma_s, 0.0f);
  medium_sigma_t_ = glm::vec4(scene.medium.sigma_t(), 0.0f);
  ambient_ = glm::vec4(scene.ambient, 0.0f);
  lobes_ = storage(lobes);
  volumes_ = storage(volumes);
}

// One RGBA32F array layer per spot or beam with a gobo, at the largest gobo's size.
void SceneFrame::upload_gobos(const Scene& scene) {
  const Image* largest = nullptr;
  int layers = 0;
  for (const Light& light : scene.lights)
    if (has_gobo(light)) {
      ++layers;
      if (!largest || light.gobo->pixels.size() > largest->pixels.size()) largest = light.gobo.get();
    }
  const int w = largest ? largest->width : 1, h = largest ? largest->height : 1;
  gobos_ = make_texture(GL_TEXTURE_2D_ARRAY, GL_RGBA32F, w, h, std::max(layers, 1));
  int layer = 0;
  for (const Light& light : scene.lights)
    if (has_gobo(light)) {
      const std::vector<glm::vec4> texels = gobo_texels(*light.gobo, w, h);
      glTextureSubImage3D(gobos_.id(), 0, 0, 0, layer++, w, h, 1, GL_RGBA, GL_FLOAT, texels.data());
    }
}

// Light records with their shadow-map kind, slot and projection.
void SceneFrame::upload_lights(const Scene& scene) {
  const Bounds bounds = scene_bounds(scene);
  std::vector<GpuLight> records;
  shadow_draws_.clear();
  shadow_layout_ = {};
  int gobo_layer = 0;
  for (const Light& light : scene.lights) {
    const int light_index = static_cast<int>(records.size());
    GpuLight g = light_record(light, has_gobo(light) ? gobo_layer++ : -1);
    g.meta.y = shadow_kind(light, bounds);
    if (g.meta.y == shadow_cube) {
      g.meta.z = shadow_layout_.cubes++;
      g.shadow = glm::vec4(2.0f, 0.0f, 0.0f, 0.0f);  // a 90° face: 2 units across at unit distance
      const auto faces = cube_face_matrices(glm::dvec3(light.position), bounds);
      for (int f = 0; f < 6; ++f) shadow_draws_.push_back({light_index, true, 6 * g.meta.z + f, faces[f]});
    } else if (g.meta.y == shadow_map) {
      g.meta.z = shadow_layout_.maps++;
      const Projection p = light.type == LightType::directional ? directional_projection(light, bounds)
                                                                  : spot_projection(light, bounds);
      g.shadow_matrix = p.matrix;
      g.shadow = glm::vec4(p.per_distance, p.constant, 0.0f, 0.0f);
      shadow_draws_.push_back({light_index, false, g.meta.z, p.matrix});
    }
    records.push_back(g);
  }
  light_count_ = static_cast<int>(records.size());
  lights_ = storage(records);
}

// ---- render ---------------------------------------------------------------------

void SceneFrame::render(int width, int height, const FrameSettings& settings, PassTimer& timer) {
  if (width <= 0 || height <= 0) throw Failure("the image size must be positive");
  resize(width, height);
  if (settings.shadow_resolution != shadow_resolution_) allocate_shadow_maps(settings.shadow_resolution);
  update_frame_block(settings);
  bind();
  {
    ScopedPass pass(timer, "gbuffer");
    draw_gbuffer();
  }
  {
    ScopedPass pass(timer, "shadow");
    draw_shadow_maps();
  }
  {
    ScopedPass pass(timer, "surface");
    shade_surfaces();
  }
}

void SceneFrame::resize(int width, int height) {
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  distance_ = render_target(GL_R32F, width, height);
  normal_ = render_target(GL_RGBA32F, width, height);
  geometric_normal_ = render_target(GL_RGBA32F, width, height);
  albedo_ = render_target(GL_RGBA32F, width, height);
  depth_ = render_target(GL_DEPTH_COMPONENT32F, width, height);
  surface_ = render_target(GL_RGBA32F, width, height);
  composite_ = render_target(GL_RGBA32F, width, height);
  const GLuint fbo = gbuffer_fbo_.id();
  const GLuint colours[] = {distance_.id(), normal_.id(), geometric_normal_.id(), albedo_.id()};
  GLenum buffers[4];
  for (GLuint k = 0; k < 4; ++k) {
    glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0 + k, colours[k], 0);
    buffers[k] = GL_COLOR_ATTACHMENT0 + k;
  }
  glNamedFramebufferDrawBuffers(fbo, 4, buffers);
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  check_complete(gbuffer_fbo_, "G-buffer");
}

// Unused kinds get a 1×1 texture so that every sampler stays bound and valid.
void SceneFrame::allocate_shadow_maps(int resolution) {
  shadow_resolution_ = resolution;
  const int maps = shadow_layout_.maps, cubes = shadow_layout_.cubes;
  const int map_size = maps ? resolution : 1, cube_size = cubes ? resolution : 1;
  shadow_maps_ = make_texture(GL_TEXTURE_2D_ARRAY, GL_R32F, map_size, map_size, std::max(maps, 1));
  shadow_cubes_ = make_texture(GL_TEXTURE_CUBE_MAP_ARRAY, GL_R32F, cube_size, cube_size, 6 * std::max(cubes, 1));
  shadow_depth_ = render_target(GL_DEPTH_COMPONENT32F, resolution, resolution);
  glNamedFramebufferTexture(shadow_fbo_.id(), GL_DEPTH_ATTACHMENT, shadow_depth_.id(), 0);
}

void SceneFrame::update_frame_block(const FrameSettings& settings) {
  const geometry::CameraFrame f = geometry::camera_frame(camera_);
  const double aspect = static_cast<double>(width_) / height_, t = f.tan_half_fov_y;
  const double n = camera_.near, far = camera_.far;
  // The frustum through the pixel grid of geometry::primary_ray: pixel centres
  // rasterize at (i + 0.5)/W of [-t·aspect, t·aspect] × [-t, t] on the unit plane.
  const glm::dmat4 proj = glm::frustum(-t * aspect * n, t * aspect * n, -t * n, t * n, n, far);
  const glm::dmat4 view = glm::lookAt(f.position, f.position + f.forward, f.up);
  FrameBlock b{};
  b.view_projection = glm::mat4(proj * view);
  b.eye = glm::vec4(glm::vec3(f.position), 1.0f);
  b.forward = glm::vec4(glm::vec3(f.forward), 0.0f);
  b.right = glm::vec4(glm::vec3(f.right), 0.0f);
  b.up = glm::vec4(glm::vec3(f.up), 0.0f);
  b.image = glm::vec4(width_, height_, t, aspect);
  b.clip = glm::vec4(camera_.near, camera_.far, settings.shadow_bias, shadow_resolution_);
  b.medium_sigma_s = medium_sigma_s_;
  b.medium_sigma_t = medium_sigma_t_;
  b.ambient = ambient_;
  b.light_model = glm::vec4(light_model_.a0, light_model_.a1, 0.0f, 0.0f);
  b.counts = glm::ivec4(light_count_, volume_count_, medium_lobes_, static_cast<int>(light_model_.type));
  glNamedBufferSubData(frame_block_.id(), 0, sizeof(b), &b);
}

void SceneFrame::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::frame_block, frame_block_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::lights, lights_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::volumes, volumes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::lobes, lobes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::face_normals, face_normals_.id());
  glBindTextureUnit(binding::distance, distance_.id());
  glBindTextureUnit(binding::normal, normal_.id());
  glBindTextureUnit(binding::geometric_normal, geometric_normal_.id());
  glBindTextureUnit(binding::albedo, albedo_.id());
  glBindTextureUnit(binding::gobos, gobos_.id());
  glBindTextureUnit(binding::shadow_maps, shadow_maps_.id());
  glBindTextureUnit(binding::shadow_cubes, shadow_cubes_.id());
}

// The far-plane background first (no depth test), then the meshes over it.
void SceneFrame::draw_gbuffer() {
  // The G-buffer textures are the pass's outputs: unbind them as inputs meanwhile.
  for (GLuint unit : {binding::distance, binding::normal, binding::geometric_normal, binding::albedo})
    glBindTextureUnit(unit, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_.id());
  glViewport(0, 0, width_, height_);
  const float one = 1.0f;
  glClearNamedFramebufferfv(gbuffer_fbo_.id(), GL_DEPTH, 0, &one);
  glBindVertexArray(vertex_array_.id());
  glDisable(GL_DEPTH_TEST);
  glUseProgram(programs_.background.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(programs_.gbuffer.id());
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bind();
}

void SceneFrame::draw_shadow_maps() {
  glBindTextureUnit(binding::shadow_maps, 0);
  glBindTextureUnit(binding::shadow_cubes, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_.id());
  glViewport(0, 0, shadow_resolution_, shadow_resolution_);
  glBindVertexArray(vertex_array_.id());
  glUseProgram(programs_.shadow.id());
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  for (const ShadowDraw& d : shadow_draws_) draw_shadow_layer(d);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bind();
}

// One 2D map or cube face: cleared to FLT_MAX (no occluder: lit), then the scene.
void SceneFrame::draw_shadow_layer(const ShadowDraw& d) {
  const GLuint texture = d.cube ? shadow_cubes_.id() : shadow_maps_.id();
  glNamedFramebufferTextureLayer(shadow_fbo_.id(), GL_COLOR_ATTACHMENT0, texture, 0, d.layer);
  check_complete(shadow_fbo_, "shadow map");
  const float far[4] = {FLT_MAX, 0.0f, 0.0f, 0.0f}, one = 1.0f;
  glClearNamedFramebufferfv(shadow_fbo_.id(), GL_COLOR, 0, far);
  glClearNamedFramebufferfv(shadow_fbo_.id(), GL_DEPTH, 0, &one);
  set_uniform(programs_.shadow, "light_view_projection", d.matrix);
  set_uniform(programs_.shadow, "light_index", d.light);
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
}

void SceneFrame::shade_surfaces() {
  glUseProgram(programs_.surface.id());
  glBindImageTexture(0, surface_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  dispatch_pixels(width_, height_);
}

void SceneFrame::composite(const Texture& airlight, PassTimer& timer) {
  ScopedPass pass(timer, "composite");
  glUseProgram(programs_.composite.id());
  glBindImageTexture(0, composite_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(1, surface_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  glBindImageTexture(2, airlight.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
  dispatch_pixels(width_, height_);
}

}  // namespace airlight::kit
