#include "methods/kit/frame/scene_frame.hpp"

#include "geometry/camera.hpp"
#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "methods/kit/frame/frame_data.hpp"
#include "methods/kit/frame/scene_defines.hpp"
#include "methods/kit/frame/shadows/shadow_projection.hpp"
#include "optics/light.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <numbers>

namespace airlight::kit {

using namespace gpu;

namespace {

using shader::FrameData;
using shader::SceneLight;
using shader::SceneLobe;
using shader::SceneVolume;

// One vertex of the scene's meshes, in its object's space.
struct Vertex {
  glm::vec3 position, normal, albedo;
  GLint object;  // index into Scene::meshes and the ObjectTransform array
};

// Per mesh (gbuffer.vert.glsl): object → world, and its inverse transpose for normals.
struct ObjectTransform {
  glm::mat4 model, normal;
};

// The lights whose gobo the GPU samples: spots and beams (a gobo means nothing elsewhere).
bool has_gobo(const Light& light) {
  return (light.type == LightType::spot || optics::has_beam(light)) && light.gobo && !light.gobo->empty();
}

SceneLight light_record(const Light& light, int gobo_layer) {
  SceneLight g{};
  const double cone = optics::radians(light.cone_deg);
  const bool spot = light.type == LightType::spot, beam = optics::has_beam(light);
  g.position = beam ? light.beam->origin : light.position;
  g.cone = spot ? static_cast<float>(cone) : 0.0f;
  g.direction = glm::normalize(light.direction);
  g.edge = spot ? static_cast<float>(optics::radians(light.edge_deg)) : 0.0f;
  g.color = light.type == LightType::directional ? light.irradiance : light.intensity;
  const bool square = spot && cone < 0.5 * std::numbers::pi;  // gobo_uv needs tan(cone) finite
  g.tan_cone = square ? static_cast<float>(std::tan(cone)) : 0.0f;
  if (spot || beam) {
    glm::dvec3 right, up;
    optics::gobo_frame(light, right, up);
    g.gobo_right = glm::vec3(right);
    g.gobo_up = glm::vec3(up);
  }
  if (beam) {
    g.beam_width = light.beam->size.x;
    g.beam_height = light.beam->size.y;
    g.beam_length = light.beam->length;
  }
  g.type = static_cast<int>(light.type);
  g.shadow_kind = shadow_none;
  g.gobo_layer = gobo_layer;
  if (gobo_layer >= 0) g.gobo_size = light.gobo->width * 65536 + light.gobo->height;
  return g;
}

// ---- textures -----------------------------------------------------------------

// The gobo's texels, rows flipped (texel row 0 = the image's bottom row: t = v, light.glsl).
std::vector<glm::vec4> gobo_texels(const Image& gobo) {
  std::vector<glm::vec4> texels(gobo.pixels.size());
  for (int y = 0; y < gobo.height; ++y)
    for (int x = 0; x < gobo.width; ++x)
      texels[static_cast<size_t>(y) * gobo.width + x] = glm::vec4(gobo.at(x, gobo.height - 1 - y), 1.0f);
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
  return make_buffer(std::max<size_t>(data.size(), 1) * sizeof(T), data.empty() ? nullptr : data.data());
}

// A frame's data into `buffer`: written in place when its size is unchanged,
// so that a frame allocates nothing.
template <typename T>
void update(Buffer& buffer, const std::vector<T>& data) {
  const size_t bytes = std::max<size_t>(data.size(), 1) * sizeof(T);
  GLint64 size = 0;
  if (buffer) glGetNamedBufferParameteri64v(buffer.id(), GL_BUFFER_SIZE, &size);
  if (static_cast<size_t>(size) != bytes)
    buffer = storage(data);
  else if (!data.empty())
    glNamedBufferSubData(buffer.id(), 0, static_cast<GLsizeiptr>(bytes), data.data());
}

const Program& frame_program(const char* vertex, const char* fragment, const std::string& defines) {
  return cached_program({{GL_VERTEX_SHADER, vertex}, {GL_FRAGMENT_SHADER, fragment}}, defines);
}

// ---- checks of a frame's inputs against the prepared scene (before any GL work) ----

// Gobos are uploaded at prepare: a frame may only use those.
void check_gobos(const FrameInputs& in, const std::vector<const Image*>& gobos) {
  for (size_t i = 0; i < in.lights.size(); ++i)
    if (has_gobo(in.lights[i]) && std::find(gobos.begin(), gobos.end(), in.lights[i].gobo.get()) == gobos.end())
      throw InputError("frame", "lights[" + std::to_string(i) + "].gobo",
                       "is not a gobo of the prepared scene's lights (gobos are uploaded at prepare)");
}

}  // namespace

std::string binding_defines() {
  using namespace binding;
  const std::pair<const char*, GLuint> all[] = {
      {"FRAME_BLOCK", frame_block},   {"LIGHTS", lights},
      {"VOLUMES", volumes},           {"LOBES", lobes},
      {"FACE_NORMALS", face_normals}, {"OBJECTS", objects},
      {"DISTANCE", distance},         {"NORMAL", normal},
      {"GEOMETRIC_NORMAL", geometric_normal}, {"ALBEDO", albedo},
      {"GOBOS", gobos},               {"SHADOW_MAPS", shadow_maps},
      {"SHADOW_CUBES", shadow_cubes}, {"ENGINE_INPUT", engine_input},
      {"FIRST_FREE_TEXTURE", first_free_texture}};
  std::string text;
  for (const auto& [name, value] : all)
    text += "#define BINDING_" + std::string(name) + " " + std::to_string(value) + "\n";
  return text;
}

// ---- prepare --------------------------------------------------------------------

void SceneFrame::prepare(const Scene& scene) {
  geometry::camera_basis(scene.camera);  // throws now for a degenerate camera
  scene_ = scene;
  upload_meshes(scene);
  upload_gobos(scene);
  frame_block_ = make_buffer(sizeof(FrameData), nullptr);
  gbuffer_fbo_ = make_framebuffer();
  shadow_fbo_ = make_framebuffer();
  nearest_ = gpu::make_nearest_sampler();
  inputs_ = FrameInputs{};
  shadow_layout_ = {};
  shadow_resolution_ = 0;
}

// One vertex buffer and one index buffer for all meshes, so that one draw covers
// the scene and gl_PrimitiveID indexes the per-triangle face normals (in object
// space; gbuffer.frag.glsl turns them with the object).
void SceneFrame::upload_meshes(const Scene& scene) {
  std::vector<Vertex> vertices;
  std::vector<GLuint> indices;
  std::vector<glm::vec4> face_normals;
  caster_bounds_.clear();
  std::vector<GLuint> bases;
  caster_index_count_ = 0;
  for (const Mesh& mesh : scene.meshes) {
    bases.push_back(static_cast<GLuint>(vertices.size()));
    const auto object = static_cast<GLint>(caster_bounds_.size());
    const bool normals = mesh.normals.size() == mesh.positions.size();
    for (size_t v = 0; v < mesh.positions.size(); ++v)
      vertices.push_back({mesh.positions[v], normals ? mesh.normals[v] : glm::vec3(0.0f), mesh.albedo, object});
    caster_bounds_.push_back(caster_bounds(mesh));
  }
  // The shadow casters' triangles first, so that the shadow maps draw them alone.
  for (const bool casters : {true, false})
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
      const Mesh& mesh = scene.meshes[m];
      if (mesh.casts_shadows != casters) continue;
      for (const glm::uvec3& t : mesh.triangles) {
        indices.insert(indices.end(), {bases[m] + t.x, bases[m] + t.y, bases[m] + t.z});
        const glm::dvec3 a(mesh.positions[t.x]), b(mesh.positions[t.y]), c(mesh.positions[t.z]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        const double length = glm::length(n);
        face_normals.emplace_back(glm::vec3(length > 0.0 ? n / length : n), 0.0f);
      }
      if (casters) caster_index_count_ = static_cast<int>(indices.size());
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
  glEnableVertexArrayAttrib(vao, 3);
  glVertexArrayAttribIFormat(vao, 3, 1, GL_INT, offsetof(Vertex, object));
  glVertexArrayAttribBinding(vao, 3, 0);
}

// One RGBA32F array layer per spot or beam with a gobo, at the largest gobo's size.
void SceneFrame::upload_gobos(const Scene& scene) {
  gobo_images_.clear();
  for (const Light& light : scene.lights)
    if (has_gobo(light) && std::find(gobo_images_.begin(), gobo_images_.end(), light.gobo.get()) == gobo_images_.end())
      gobo_images_.push_back(light.gobo.get());
  int w = 1, h = 1;
  for (const Image* gobo : gobo_images_) {
    w = std::max(w, gobo->width);
    h = std::max(h, gobo->height);
  }
  gobos_ = make_texture(GL_TEXTURE_2D_ARRAY, GL_RGBA32F, w, h, std::max(static_cast<int>(gobo_images_.size()), 1));
  for (size_t layer = 0; layer < gobo_images_.size(); ++layer) {
    const Image& gobo = *gobo_images_[layer];
    const std::vector<glm::vec4> texels = gobo_texels(gobo);
    glTextureSubImage3D(gobos_.id(), 0, 0, 0, static_cast<GLint>(layer), gobo.width, gobo.height, 1, GL_RGBA, GL_FLOAT,
                        texels.data());
  }
}

// ---- a frame's inputs -----------------------------------------------------------

void SceneFrame::upload_inputs(const FrameSettings& settings, const EngineFrame* engine, bool shadows) {
  std::vector<ObjectTransform> objects;
  for (size_t m = 0; m < scene_.meshes.size(); ++m) {
    const glm::mat4 model = inputs_.transforms.empty() ? glm::mat4(1.0f) : inputs_.transforms[m];
    objects.push_back({model, glm::transpose(glm::inverse(model))});
  }
  update(objects_, objects);
  const Media media = upload_medium();
  const std::vector<SceneLight> lights = upload_lights(engine, settings.shadow_resolution, shadows);
  defines_ = binding_defines() + structure_defines(lights, media.volumes, media.lobes,
                                                   static_cast<int>(inputs_.medium.phase.lobes.size()), inputs_);
  update_frame_block(settings);
}

// The frame's medium lobes first (lobes[0 .. medium_lobes)), then each volume's.
SceneFrame::Media SceneFrame::upload_medium() {
  std::vector<SceneLobe> lobes;
  auto append = [&](const Phase& phase) {
    const int first = static_cast<int>(lobes.size());
    for (const PhaseLobe& l : phase.lobes) lobes.push_back({static_cast<int>(l.type), l.g, l.weight, 0.0f});
    return first;
  };
  append(inputs_.medium.phase);
  std::vector<SceneVolume> volumes;
  for (const Volume& v : scene_.volumes) {
    const int first = append(v.phase);
    volumes.push_back({v.min, first, v.max, static_cast<int>(v.phase.lobes.size()), v.sigma_s, 0.0f, v.sigma_t(), 0.0f});
  }
  update(lobes_, lobes);
  update(volumes_, volumes);
  return {std::move(lobes), std::move(volumes)};
}

// Light records with their shadow-map kind, slot and projection: airlight's
// own, or those of the engine's map, converted into airlight's layer; none
// at all when the frame's method reads no shadow map.
std::vector<SceneLight> SceneFrame::upload_lights(const EngineFrame* engine, int resolution, bool shadows) {
  const Bounds bounds = world_bounds(caster_bounds_, inputs_.transforms);
  std::vector<SceneLight> records;
  shadow_draws_.clear();
  shadow_kinds_.clear();
  ShadowLayout layout;
  for (const Light& light : inputs_.lights) {
    const int index = static_cast<int>(records.size());
    const EngineShadow* theirs =
        engine && index < static_cast<int>(engine->shadows.size()) && engine->shadows[index] ? &*engine->shadows[index]
                                                                                              : nullptr;
    const auto gobo = std::find(gobo_images_.begin(), gobo_images_.end(), light.gobo.get());
    SceneLight g = light_record(light, has_gobo(light) ? static_cast<int>(gobo - gobo_images_.begin()) : -1);
    g.shadow_kind = shadows ? shadow_kind(light, bounds, theirs) : shadow_none;
    if (g.shadow_kind == shadow_cube) {
      g.shadow_layer = layout.cubes++;
      g.texel_per_distance = 2.0f;  // a 90° face: 2 units across at unit distance
      const auto faces = cube_face_matrices(glm::dvec3(light.position), bounds);
      for (int f = 0; f < 6; ++f) shadow_draws_.push_back({index, true, 6 * g.shadow_layer + f, faces[f], theirs});
    } else if (g.shadow_kind == shadow_map) {
      g.shadow_layer = layout.maps++;
      const Projection p = theirs ? engine_projection(*theirs)
                           : light.type == LightType::directional ? directional_projection(light, bounds)
                                                                   : spot_projection(light, bounds);
      g.shadow_matrix = p.matrix;
      g.texel_per_distance = p.per_distance;
      g.texel_constant = p.constant;
      shadow_draws_.push_back({index, false, g.shadow_layer, p.matrix, theirs});
    }
    records.push_back(g);
    shadow_kinds_.push_back(g.shadow_kind);
  }
  update(lights_, records);
  if (!(layout == shadow_layout_) || resolution != shadow_resolution_) allocate_shadow_maps(layout, resolution);
  return records;
}

// ---- render ---------------------------------------------------------------------

void SceneFrame::render(const FrameInputs& inputs, const FrameSettings& settings, const EngineFrame* engine,
                        Needs needs, PassTimer& timer) {
  check_frame_inputs(scene_, inputs);
  check_gobos(inputs, gobo_images_);
  geometry::camera_basis(inputs.camera);  // throws for a degenerate camera
  resize(inputs.width, inputs.height);
  inputs_ = inputs;
  upload_inputs(settings, engine, needs.shadows);
  bind();
  {
    ScopedPass pass(timer, engine && engine->depth ? "depth" : "gbuffer");
    if (engine && engine->depth)
      import_depth(*engine->depth);
    else
      draw_gbuffer();
  }
  if (needs.shadows) {
    ScopedPass pass(timer, "shadow");
    draw_shadow_maps();
  }
  if (needs.surface) {
    ScopedPass pass(timer, "surface");
    shade_surfaces();
  } else {
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(surface_.id(), 0, GL_RGBA, GL_FLOAT, zero);
  }
}

void SceneFrame::resize(int width, int height) {
  if (distance_ && width == inputs_.width && height == inputs_.height) return;
  gpu::Context::current().check_frame_size(width, height);
  distance_ = render_target(GL_R32F, width, height);
  normal_ = render_target(GL_RGBA32F, width, height);
  geometric_normal_ = render_target(GL_RGBA32F, width, height);
  albedo_ = render_target(GL_RGBA32F, width, height);
  depth_ = render_target(GL_DEPTH_COMPONENT32F, width, height);
  surface_ = render_target(GL_RGBA32F, width, height);
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
void SceneFrame::allocate_shadow_maps(const ShadowLayout& layout, int resolution) {
  shadow_layout_ = layout;
  shadow_resolution_ = resolution;
  const int maps = layout.maps, cubes = layout.cubes;
  const int map_size = maps ? resolution : 1, cube_size = cubes ? resolution : 1;
  shadow_maps_ = make_texture(GL_TEXTURE_2D_ARRAY, GL_R32F, map_size, map_size, std::max(maps, 1));
  shadow_cubes_ = make_texture(GL_TEXTURE_CUBE_MAP_ARRAY, GL_R32F, cube_size, cube_size, 6 * std::max(cubes, 1));
  shadow_depth_ = render_target(GL_DEPTH_COMPONENT32F, resolution, resolution);
  glNamedFramebufferTexture(shadow_fbo_.id(), GL_DEPTH_ATTACHMENT, shadow_depth_.id(), 0);
}

void SceneFrame::update_frame_block(const FrameSettings& settings) {
  const Camera& camera = inputs_.camera;
  const geometry::CameraBasis f = geometry::camera_basis(camera);
  const double aspect = static_cast<double>(inputs_.width) / inputs_.height, t = f.tan_half_fov_y;
  const double n = camera.near, far = camera.far;
  // The frustum through the pixel grid of geometry::primary_ray: pixel centres
  // rasterize at (i + 0.5)/W of [-t·aspect, t·aspect] × [-t, t] on the unit plane.
  const glm::dmat4 proj = glm::frustum(-t * aspect * n, t * aspect * n, -t * n, t * n, n, far);
  const glm::dmat4 view = glm::lookAt(f.position, f.position + f.forward, f.up);
  FrameData b{};
  b.view_projection = glm::mat4(proj * view);
  b.eye = glm::vec3(f.position);
  b.near_plane = camera.near;
  b.forward = glm::vec3(f.forward);
  b.far_plane = camera.far;
  b.right = glm::vec3(f.right);
  b.tan_half_fov_y = static_cast<float>(t);
  b.up = glm::vec3(f.up);
  b.aspect = static_cast<float>(aspect);
  b.medium_sigma_s = inputs_.medium.sigma_s;
  b.shadow_bias = settings.shadow_bias;
  b.medium_sigma_t = inputs_.medium.sigma_t();
  b.shadow_resolution = static_cast<float>(shadow_resolution_);
  b.ambient = scene_.ambient;
  b.light_model_a0 = inputs_.light_model.a0;
  b.size = glm::vec2(inputs_.width, inputs_.height);
  b.light_model_a1 = inputs_.light_model.a1;
  b.light_model = static_cast<int>(inputs_.light_model.type);
  b.light_count = light_count();
  b.volume_count = static_cast<int>(scene_.volumes.size());
  b.medium_lobes = static_cast<int>(inputs_.medium.phase.lobes.size());
  glNamedBufferSubData(frame_block_.id(), 0, sizeof(b), &b);
}

void SceneFrame::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::frame_block, frame_block_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::lights, lights_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::volumes, volumes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::lobes, lobes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::face_normals, face_normals_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::objects, objects_.id());
  glBindTextureUnit(binding::distance, distance_.id());
  glBindTextureUnit(binding::normal, normal_.id());
  glBindTextureUnit(binding::geometric_normal, geometric_normal_.id());
  glBindTextureUnit(binding::albedo, albedo_.id());
  glBindTextureUnit(binding::gobos, gobos_.id());
  glBindTextureUnit(binding::shadow_maps, shadow_maps_.id());
  glBindTextureUnit(binding::shadow_cubes, shadow_cubes_.id());
  for (GLuint unit = 0; unit < binding::first_free_texture; ++unit) glBindSampler(unit, 0);
}

void SceneFrame::draw_gbuffer() {
  // The G-buffer textures are the pass's outputs: unbind them as inputs meanwhile.
  for (GLuint unit : {binding::distance, binding::normal, binding::geometric_normal, binding::albedo})
    glBindTextureUnit(unit, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_.id());
  glViewport(0, 0, inputs_.width, inputs_.height);
  const float one = 1.0f;
  glClearNamedFramebufferfv(gbuffer_fbo_.id(), GL_DEPTH, 0, &one);
  glBindVertexArray(vertex_array_.id());
  glDisable(GL_DEPTH_TEST);  // the far-plane background first, then the meshes over it
  glUseProgram(frame_program("methods/kit/frame/fullscreen.vert.glsl", "methods/kit/frame/background.frag.glsl", defines_).id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(frame_program("methods/kit/frame/gbuffer.vert.glsl", "methods/kit/frame/gbuffer.frag.glsl", defines_).id());
  glDrawElements(GL_TRIANGLES, index_count_, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_DEPTH_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bind();
}

// The engine's depth buffer as airlight's G-buffer: eye distances, and window
// depths of airlight's own projection for methods that depth-test (depth.frag.glsl).
void SceneFrame::import_depth(const EngineDepth& depth) {
  for (GLuint unit : {binding::distance, binding::normal, binding::geometric_normal, binding::albedo})
    glBindTextureUnit(unit, 0);
  const Program& program = frame_program("methods/kit/frame/fullscreen.vert.glsl", "methods/kit/frame/depth.frag.glsl", defines_);
  const glm::mat4 view_projection = depth.projection * depth.view;
  set_uniform(program, "engine_inverse_view_projection", glm::inverse(view_projection));
  set_uniform(program, "engine_zero_to_one", depth.range == DepthRange::zero_to_one ? 1 : 0);
  set_uniform(program, "engine_far_depth", far_window_depth(depth.projection));
  glBindTextureUnit(binding::engine_input, depth.texture);
  glBindSampler(binding::engine_input, nearest_.id());
  glBindFramebuffer(GL_FRAMEBUFFER, gbuffer_fbo_.id());
  glViewport(0, 0, inputs_.width, inputs_.height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_ALWAYS);  // gl_FragDepth is written, not tested
  glBindVertexArray(vertex_array_.id());
  glUseProgram(program.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  glBindSampler(binding::engine_input, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bind();
}

void SceneFrame::draw_shadow_maps() {
  glBindTextureUnit(binding::shadow_maps, 0);
  glBindTextureUnit(binding::shadow_cubes, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_.id());
  glViewport(0, 0, shadow_resolution_, shadow_resolution_);
  glBindVertexArray(vertex_array_.id());
  for (const ShadowDraw& d : shadow_draws_) {
    const GLuint texture = d.cube ? shadow_cubes_.id() : shadow_maps_.id();
    glNamedFramebufferTextureLayer(shadow_fbo_.id(), GL_COLOR_ATTACHMENT0, texture, 0, d.layer);
    check_complete(shadow_fbo_, "shadow map");
    if (d.engine)
      import_shadow_layer(d);
    else
      draw_shadow_layer(d);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  bind();
}

// One 2D map or cube face: cleared to FLT_MAX (no occluder: lit), then the scene.
void SceneFrame::draw_shadow_layer(const ShadowDraw& d) {
  const float far[4] = {FLT_MAX, 0.0f, 0.0f, 0.0f}, one = 1.0f;
  glClearNamedFramebufferfv(shadow_fbo_.id(), GL_COLOR, 0, far);
  glClearNamedFramebufferfv(shadow_fbo_.id(), GL_DEPTH, 0, &one);
  const Program& program = frame_program("methods/kit/frame/shadows/shadow.vert.glsl", "methods/kit/frame/shadows/shadow.frag.glsl", defines_);
  glUseProgram(program.id());
  set_uniform(program, "light_view_projection", d.matrix);
  set_uniform(program, "light_index", d.light);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDrawElements(GL_TRIANGLES, caster_index_count_, GL_UNSIGNED_INT, nullptr);
  glDisable(GL_DEPTH_TEST);
}

// One layer converted from the engine's map: each texel's stored depth turned
// into the distance airlight's lookups compare with (shadow_import.frag.glsl).
void SceneFrame::import_shadow_layer(const ShadowDraw& d) {
  const EngineShadow& e = *d.engine;
  const bool cube = e.kind == EngineShadow::Kind::cube;
  const std::string defines = cube ? "#define ENGINE_CUBE\n" : e.layer >= 0 ? "#define ENGINE_ARRAY\n" : "";
  const Program& program =
      cached_program({{GL_VERTEX_SHADER, "methods/kit/frame/fullscreen.vert.glsl"},
                      {GL_FRAGMENT_SHADER, "methods/kit/frame/shadows/shadow_import.frag.glsl"}},
                     defines_ + defines);
  glUseProgram(program.id());
  set_uniform(program, "light_index", d.light);
  set_uniform(program, "face", d.layer % 6);
  set_uniform(program, "engine_layer", std::max(e.layer, 0));
  set_uniform(program, "engine_distance", e.stores == EngineShadow::Stores::distance ? 1 : 0);
  set_uniform(program, "engine_inverse_view_projection", glm::inverse(cube ? e.projection : d.matrix));
  set_uniform(program, "engine_zero_to_one", e.range == DepthRange::zero_to_one ? 1 : 0);
  set_uniform(program, "engine_far_depth", far_window_depth(e.projection));
  glBindTextureUnit(binding::engine_input, e.texture);
  glBindSampler(binding::engine_input, nearest_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindSampler(binding::engine_input, 0);
}

void SceneFrame::shade_surfaces() {
  glUseProgram(cached_compute_program("methods/kit/frame/surface.comp.glsl", defines_).id());
  glBindImageTexture(0, surface_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  dispatch_pixels(inputs_.width, inputs_.height);
}

}  // namespace airlight::kit
