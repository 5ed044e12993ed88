#include "methods/kit/frame/scene_frame.hpp"

#include "geometry/camera.hpp"
#include "methods/kit/frame/frame_data.hpp"
#include "methods/kit/frame/model_of.hpp"
#include "methods/kit/frame/scene_defines.hpp"
#include "methods/kit/frame/scene_frame_parts.hpp"
#include "methods/kit/frame/shadows/engine_projection.hpp"
#include "methods/kit/frame/shadows/shadow_projection.hpp"
#include "optics/light.hpp"

#include <algorithm>
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

// The gobo's texels, rows flipped (texel row 0 = the image's bottom row: t = v, light.glsl).
std::vector<glm::vec4> gobo_texels(const Image& gobo) {
  std::vector<glm::vec4> texels(gobo.pixels.size());
  for (int y = 0; y < gobo.height; ++y)
    for (int x = 0; x < gobo.width; ++x)
      texels[static_cast<size_t>(y) * gobo.width + x] = glm::vec4(gobo.at(x, gobo.height - 1 - y), 1.0f);
  return texels;
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

}  // namespace

// ---- what the scene fixes, at prepare --------------------------------------------

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
    const glm::mat4 model = model_of(inputs_.transforms, m);
    objects.push_back({model, glm::transpose(glm::inverse(model))});
  }
  update(objects_, objects);
  const Media media = upload_medium();
  const std::vector<SceneLight> lights = upload_lights(engine, settings.shadow_resolution, shadows);
  defines_ = binding_defines() + structure_defines(lights, media.volumes, media.lobes,
                                                   static_cast<int>(inputs_.medium.phase.lobes.size()), inputs_);
  representatives_ = structure_representatives(lights);
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

}  // namespace airlight::kit
