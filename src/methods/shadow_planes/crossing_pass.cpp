#include "methods/shadow_planes/crossing_pass.hpp"

#include "gpu/program.hpp"

#include <algorithm>
#include <chrono>
#include <glm/vec4.hpp>

namespace airlight::methods {
namespace {

constexpr GLuint planes_binding = kit::binding::first_free_storage;
constexpr GLuint nodes_binding = planes_binding + 1;
constexpr GLuint node_count_binding = planes_binding + 2;
constexpr GLuint end_of_list = 0xffffffffu;
constexpr size_t node_bytes = 3 * sizeof(GLuint);

// One plane as crossings.glsl's ShadowPlane: a = (a, weight), b = (b, light),
// plane = (n, n·x) for its unit normal n and any point x of it.
struct GpuPlane {
  glm::vec4 a, b, plane;
};

// The plane's unit normal, in double: n = (a − L) × (b − L), or D × (b − a) for
// a directional light (geometry/shadow_edges.hpp). In float, a short edge far
// from the light loses n's direction to cancellation, and a crossing's sign
// with it; normalized in double, its sign is right wherever the ray does not
// graze the plane.
glm::vec4 plane_equation(const geometry::ShadowPlane& p, const Light& light) {
  const glm::dvec3 a(p.a), b(p.b);
  const bool directional = light.type == LightType::directional;
  const glm::dvec3 l(light.position), n = directional ? glm::cross(glm::dvec3(light.direction), b - a)
                                                      : glm::cross(a - l, b - l);
  const double length = glm::length(n);
  const glm::dvec3 unit = length > 0.0 ? n / length : n;
  return glm::vec4(glm::vec3(unit), static_cast<float>(glm::dot(unit, directional ? a : l)));
}

}  // namespace

std::string CrossingPass::defines() {
  return "#define BINDING_PLANES " + std::to_string(planes_binding) + "\n#define BINDING_NODES " +
         std::to_string(nodes_binding) + "\n#define BINDING_NODE_COUNT " + std::to_string(node_count_binding) + "\n";
}

void CrossingPass::prepare(const Scene& scene) {
  casters_.clear();
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    if (!mesh.casts_shadows) continue;
    casters_.push_back({static_cast<int>(m), geometry::build_topology(mesh.positions, mesh.triangles), {}});
  }
  fbo_ = gpu::make_framebuffer();
  no_vertices_ = gpu::make_vertex_array();  // the planes come from their buffer by gl_VertexID
  node_count_ = gpu::make_buffer(2 * sizeof(GLuint), nullptr);
}

// Per caster its welded positions moved by the frame's transform, then per
// light the planes of every caster and the eye's count (Biri §5.1.1: the
// silhouettes depend on the light and the caster, so both are rebuilt every frame).
void CrossingPass::build_planes(const FrameInputs& inputs) {
  const auto start = std::chrono::steady_clock::now();
  for (Caster& c : casters_) {
    const glm::mat4 m = inputs.transforms.empty() ? glm::mat4(1.0f) : inputs.transforms[c.mesh];
    c.world.resize(c.topology.positions.size());
    std::transform(c.topology.positions.begin(), c.topology.positions.end(), c.world.begin(),
                   [&m](const glm::vec3& p) { return glm::vec3(m * glm::vec4(p, 1.0f)); });
  }
  planes_.clear();
  plane_lights_.clear();
  eye_counts_.assign(inputs.lights.size(), 0);
  silhouette_edges_ = boundary_edges_ = loops_ = 0;
  for (size_t i = 0; i < inputs.lights.size(); ++i) {
    const geometry::LightOrigin light = geometry::light_origin(inputs.lights[i]);
    for (const Caster& c : casters_) {
      const geometry::ShadowPlaneStats s = geometry::append_shadow_planes(c.topology, c.world, light, planes_);
      silhouette_edges_ += s.silhouette_edges;
      boundary_edges_ += s.boundary_edges;
      eye_counts_[i] += geometry::shadow_count(c.topology, c.world, light, inputs.camera.position);
    }
    plane_lights_.resize(planes_.size(), static_cast<int>(i));
  }
  build_s_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const Light& light : inputs.lights)  // for the report, outside build_s: it allocates
    for (const Caster& c : casters_) loops_ += geometry::shadow_plane_loops(c.topology, c.world, geometry::light_origin(light));
}

void CrossingPass::allocate_pool(size_t nodes) {
  node_capacity_ = nodes;
  nodes_ = gpu::make_buffer(node_capacity_ * node_bytes, nullptr);
}

void CrossingPass::run(const kit::SceneFrame& frame) {
  build_planes(frame.inputs());
  std::vector<GpuPlane> gpu_planes(planes_.size());
  for (size_t k = 0; k < planes_.size(); ++k)
    gpu_planes[k] = {glm::vec4(planes_[k].a, static_cast<float>(planes_[k].weight)),
                     glm::vec4(planes_[k].b, static_cast<float>(plane_lights_[k])),
                     plane_equation(planes_[k], frame.inputs().lights[plane_lights_[k]])};
  if (gpu_planes.size() > plane_capacity_ || plane_buffer_.id() == 0) {
    plane_capacity_ = std::max<size_t>(gpu_planes.size(), 1);
    plane_buffer_ = gpu::make_buffer(plane_capacity_ * sizeof(GpuPlane), nullptr);
  }
  if (!gpu_planes.empty())
    glNamedBufferSubData(plane_buffer_.id(), 0, gpu_planes.size() * sizeof(GpuPlane), gpu_planes.data());
  if (frame.width() != width_ || frame.height() != height_) {
    width_ = frame.width();
    height_ = frame.height();
    heads_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32UI, width_, height_);
    glNamedFramebufferParameteri(fbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, width_);
    glNamedFramebufferParameteri(fbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, height_);
  }
  const auto wanted = static_cast<size_t>(static_cast<double>(width_) * height_ * capacity_per_pixel_);
  if (node_capacity_ == 0 || nodes_.id() == 0) allocate_pool(std::max<size_t>(wanted, 1));
  redraws_ = 0;
  draw(frame);
  while (crossings_ > node_capacity_) {  // some pixel's crossings did not fit: a larger pool, drawn again
    allocate_pool(crossings_ + crossings_ / 4);
    ++redraws_;
    draw(frame);
  }
}

void CrossingPass::bind() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, planes_binding, plane_buffer_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, nodes_binding, nodes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, node_count_binding, node_count_.id());
}

// The planes rasterized over an attachment-less framebuffer: no depth test
// (each fragment compares its t with the G-buffer distance), no culling (both
// sides of a plane count), no near or far clipping (GL_DEPTH_CLAMP).
void CrossingPass::draw(const kit::SceneFrame& frame) {
  const GLuint empty = end_of_list;
  glClearTexImage(heads_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
  const GLuint counters[2] = {0, static_cast<GLuint>(std::min<size_t>(node_capacity_, 0xffffffffu))};
  glNamedBufferSubData(node_count_.id(), 0, sizeof(counters), counters);
  crossings_ = 0;
  if (planes_.empty()) return;
  const gpu::Program& program = gpu::cached_program(
      {{GL_VERTEX_SHADER, "methods/shadow_planes/crossings.vert.glsl"},
       {GL_FRAGMENT_SHADER, "methods/shadow_planes/crossings.frag.glsl"}},
      frame.defines() + defines());
  glUseProgram(program.id());
  bind();
  glBindImageTexture(0, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_CLAMP);
  glBindVertexArray(no_vertices_.id());
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * planes_.size()));
  glDisable(GL_DEPTH_CLAMP);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(node_count_.id(), 0, sizeof(GLuint), &crossings_);
}

std::vector<std::pair<std::string, double>> CrossingPass::stats() const {
  double triangles = 0.0;
  for (const Caster& c : casters_) triangles += static_cast<double>(c.topology.triangles.size());
  std::vector<std::pair<std::string, double>> s{{"caster_triangles", triangles},
                                                {"planes", static_cast<double>(planes_.size())},
                                                {"crossings", static_cast<double>(crossings_)},
                                                {"silhouette_edges", static_cast<double>(silhouette_edges_)},
                                                {"boundary_edges", static_cast<double>(boundary_edges_)},
                                                {"silhouette_loops", static_cast<double>(loops_)},
                                                {"build_s", build_s_},
                                                {"redraws", static_cast<double>(redraws_)}};
  for (const Caster& c : casters_)
    s.emplace_back("caster" + std::to_string(c.mesh) + (c.topology.closed ? "_silhouettes" : "_triangle_volumes"), 1.0);
  return s;
}

}  // namespace airlight::methods
