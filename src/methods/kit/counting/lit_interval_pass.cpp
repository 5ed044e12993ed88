#include "methods/kit/counting/lit_interval_pass.hpp"

#include "core/warning.hpp"
#include "gpu/program.hpp"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace airlight::kit {
namespace {

constexpr GLuint counted_binding = binding::first_free_storage;
constexpr GLuint nodes_binding = counted_binding + 1;
constexpr GLuint node_count_binding = counted_binding + 2;
constexpr GLuint kept_binding = counted_binding + 3, kept_draw_binding = counted_binding + 4;  // CountedDraw's
constexpr GLuint end_of_list = 0xffffffffu;
constexpr size_t node_bytes = 3 * sizeof(GLuint);

}  // namespace

SettingSpec gamma_samples_setting() {
  return {"samples", SettingSpec::Type::integer, 64, 1, 1024, {},
          "points per lit interval where what Γ has no closed form for — a gobo's colours, the light's leg "
          "through other bounded volumes — is sampled: Γ times the ratio of the exact in-scattering to Γ's "
          "integrand there (even in the angle seen from a spot, uniform along a beam); unused without gobos and "
          "volumes"};
}

std::vector<SettingSpec> lit_interval_settings() {
  return {{"capacity", SettingSpec::Type::real, 4.0, 0.01, 256.0, {},
           "crossings per pixel (on average over the image) the node pool holds at first; a frame with more grows "
           "the pool and draws again, so no crossing is ever dropped (the report's `redraws`)"},
          gamma_samples_setting()};
}

std::vector<MemoryNeed> crossing_pool_needs(const Settings& settings, int width, int height) {
  const double measured_with = lit_interval_settings().front().default_value;
  const double capacity = settings.real("capacity");
  char per_pixel[32];
  std::snprintf(per_pixel, sizeof per_pixel, "%g", capacity);
  return {{"capacity",
           "its crossing pool (" + std::string(per_pixel) + " crossings of " + std::to_string(node_bytes) +
               " bytes per pixel at " + std::to_string(width) + "x" + std::to_string(height) + ")",
           double(width) * height * std::max(capacity - measured_with, 0.0) * node_bytes,
           double(width) * height * capacity * node_bytes}};
}

MemoryNeed counted_triangle_need(const std::string& what, double count) {
  const double buffer = count * sizeof(CountedTriangle);
  return {"", what, 2.0 * buffer + count * sizeof(GLuint), buffer};  // and the kept indices (CountedDraw)
}

LitIntervalPass::LitIntervalPass(const Settings& s)
    : capacity_per_pixel_(s.real("capacity")), samples_(s.integer("samples")) {}

void CountedDraw::prepare() {
  fbo_ = gpu::make_framebuffer();
  no_vertices_ = gpu::make_vertex_array();  // the triangles come from their buffer by gl_VertexID
  kept_draw_ = gpu::make_buffer(4 * sizeof(GLuint), nullptr);
  kept_capacity_ = 0;
  // A storage binding holds at most GL_MAX_SHADER_STORAGE_BLOCK_SIZE bytes
  // (128 MiB on llvmpipe: 1.68 M triangles); larger sets are drawn in ranges
  // whose offsets keep the binding's alignment.
  GLint64 block = 0;
  GLint align = 16;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_OFFSET_ALIGNMENT, &align);
  const size_t step = static_cast<size_t>(align) / std::gcd(static_cast<size_t>(align), sizeof(CountedTriangle));
  range_triangles_ = std::max<size_t>(static_cast<size_t>(block) / sizeof(CountedTriangle) / step * step, step);
  if (epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query")) {
    GLuint id = 0;
    glGenQueries(1, &id);  // Mesa's glCreateQueries refuses the statistics targets
    invocations_ = gpu::Query(id);
  }
}

// The bound range's triangles that may cross a pixel's ray, into kept_ and the
// indirect draw's count (cull_counted.comp.glsl).
void CountedDraw::keep_crossing(const SceneFrame& frame, size_t n) {
  if (n > kept_capacity_) {
    kept_capacity_ = n;
    kept_ = gpu::make_buffer(n * sizeof(GLuint), nullptr);
  }
  const GLuint command[4] = {0, 1, 0, 0};  // vertex count, instances, first vertex, base instance
  glNamedBufferSubData(kept_draw_.id(), 0, sizeof(command), command);
  const gpu::Program& cull =
      gpu::cached_compute_program("methods/kit/counting/cull_counted.comp.glsl", frame.defines() + lit_interval_defines());
  glUseProgram(cull.id());
  gpu::set_uniform(cull, "item_count", static_cast<int>(n));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kept_binding, kept_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kept_draw_binding, kept_draw_.id());
  const GLuint groups = static_cast<GLuint>((n + 63) / 64), x = std::min<GLuint>(groups, 65535u);
  glDispatchCompute(x, (groups + x - 1) / x, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, kept_draw_.id());
}

double CountedDraw::draw(const SceneFrame& frame, const gpu::Program& program, const gpu::Buffer& triangles,
                         size_t count) {
  if (count == 0) return 0.0;
  if (frame.width() != width_ || frame.height() != height_) {
    width_ = frame.width();
    height_ = frame.height();
    glNamedFramebufferParameteri(fbo_.id(), GL_FRAMEBUFFER_DEFAULT_WIDTH, width_);
    glNamedFramebufferParameteri(fbo_.id(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, height_);
  }
  glUseProgram(program.id());
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
  glViewport(0, 0, width_, height_);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_CLAMP);
  glBindVertexArray(no_vertices_.id());
  if (invocations_) glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, invocations_.id());
  for (size_t first = 0; first < count; first += range_triangles_) {
    const size_t n = std::min(range_triangles_, count - first);
    glBindBufferRange(GL_SHADER_STORAGE_BUFFER, counted_binding, triangles.id(),
                      static_cast<GLintptr>(first * sizeof(CountedTriangle)),
                      static_cast<GLsizeiptr>(n * sizeof(CountedTriangle)));
    keep_crossing(frame, n);
    glUseProgram(program.id());
    glDrawArraysIndirect(GL_TRIANGLES, nullptr);
  }
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  GLuint64 fragments = 0;
  if (invocations_) {
    glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
    glGetQueryObjectui64v(invocations_.id(), GL_QUERY_RESULT, &fragments);
  }
  glDisable(GL_DEPTH_CLAMP);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  return static_cast<double>(fragments);
}

void LitIntervalPass::prepare() {
  counted_draw_.prepare();
  loop_limit_ = gpu::software_renderer();
  node_count_ = gpu::make_buffer(4 * sizeof(GLuint), nullptr);  // CountBlock
}

std::string lit_interval_defines() {
  return "#define BINDING_COUNTED " + std::to_string(counted_binding) + "\n#define BINDING_NODES " +
         std::to_string(nodes_binding) + "\n#define BINDING_NODE_COUNT " + std::to_string(node_count_binding) +
         "\n#define BINDING_KEPT " + std::to_string(kept_binding) + "\n#define BINDING_KEPT_DRAW " +
         std::to_string(kept_draw_binding) + "\n";
}

std::string LitIntervalPass::defines() const {
  std::string d = lit_interval_defines() + "#define SAMPLES " + std::to_string(samples_) + "\n";
  if (loop_limit_) d += "#define LOOP_LIMIT " + std::to_string(gpu::software_loop_limit) + "\n";
  return d;
}

void LitIntervalPass::allocate_pool(size_t nodes) {
  node_capacity_ = nodes;
  nodes_ = gpu::make_buffer(node_capacity_ * node_bytes, nullptr);
}

void LitIntervalPass::run(const SceneFrame& frame, const CrossingGeometry& geometry, const gpu::Texture& target,
                          gpu::PassTimer& timer) {
  const EyeCounts eye = geometry.eye_counts();  // before the pass: the light volume mesh's are read from the GPU
  const CountedTriangles triangles = geometry.triangles();
  {
    gpu::ScopedPass pass(timer, "crossings");
    list_crossings(frame, triangles.on_gpu ? *triangles.on_gpu : upload(triangles.on_cpu), triangles.size());
  }
  gpu::ScopedPass pass(timer, "airlight");
  resolve(frame, eye, target);
}

const gpu::Buffer& LitIntervalPass::upload(std::span<const CountedTriangle> triangles) {
  if (triangles.size() > triangle_capacity_ || triangles_.id() == 0) {
    triangle_capacity_ = std::max<size_t>(triangles.size(), 1);
    triangles_ = gpu::make_buffer(triangle_capacity_ * sizeof(CountedTriangle), nullptr);
  }
  if (!triangles.empty())
    glNamedBufferSubData(triangles_.id(), 0, triangles.size() * sizeof(CountedTriangle), triangles.data());
  return triangles_;
}

// Every pixel's list of crossings, the pool grown and the triangles drawn
// again until every crossing fits.
void LitIntervalPass::list_crossings(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count) {
  if (frame.width() != width_ || frame.height() != height_) {
    width_ = frame.width();
    height_ = frame.height();
    heads_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32UI, width_, height_);
    if (loop_limit_) progress_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32UI, width_, height_);
  }
  if (nodes_.id() == 0)
    allocate_pool(std::max<size_t>(static_cast<size_t>(double(width_) * height_ * capacity_per_pixel_), 1));
  redraws_ = 0;
  draw(frame, triangles, triangle_count);
  while (crossings_ > node_capacity_) {  // some crossings did not fit: a larger pool, drawn again
    allocate_pool(crossings_ + crossings_ / 4);
    ++redraws_;
    draw(frame, triangles, triangle_count);
  }
}

// Every crossing into the pixels' lists, from heads cleared to empty.
void LitIntervalPass::draw(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count) {
  const GLuint empty = end_of_list;
  glClearTexImage(heads_.id(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
  const GLuint counters[2] = {0, static_cast<GLuint>(std::min<size_t>(node_capacity_, end_of_list))};
  glNamedBufferSubData(node_count_.id(), 0, sizeof(counters), counters);
  crossings_ = 0;
  const gpu::Program& program = gpu::cached_program(
      {{GL_VERTEX_SHADER, "methods/kit/counting/crossings.vert.glsl"}, {GL_FRAGMENT_SHADER, "methods/kit/counting/crossings.frag.glsl"}},
      frame.defines() + defines() + CountedDraw::defines());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, nodes_binding, nodes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, node_count_binding, node_count_.id());
  glBindImageTexture(0, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  fragments_ = counted_draw_.draw(frame, program, triangles, triangle_count);
  if (triangle_count > 0) glGetNamedBufferSubData(node_count_.id(), 0, sizeof(GLuint), &crossings_);
}

void LitIntervalPass::resolve(const SceneFrame& frame, const EyeCounts& eye, const gpu::Texture& target) {
  const gpu::Program& program =
      gpu::cached_compute_program("methods/kit/counting/lit_intervals.comp.glsl", frame.defines() + defines());
  glUseProgram(program.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, nodes_binding, nodes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, node_count_binding, node_count_.id());
  gpu::set_uniform(program, "eye_counts", eye.counts);
  gpu::set_uniform(program, "eye_plane_count", static_cast<int>(eye.planes.size()));
  if (!eye.planes.empty()) {
    std::vector<glm::vec4> planes;
    std::vector<int> weights;
    for (const EyePlane& p : eye.planes) {
      planes.emplace_back(p.normal, static_cast<float>(p.light));
      weights.push_back(p.weight);
    }
    gpu::set_uniform(program, "eye_planes", planes);
    gpu::set_uniform(program, "eye_plane_weights", weights);
  }
  loop_limited_ = 0;
  passes_ = 1;
  if (!loop_limit_) {
    glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(1, heads_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
    gpu::dispatch_pixels(frame.width(), frame.height());
    return;
  }
  resolve_in_passes(frame, program, target);
}

// llvmpipe: passes while some pixel is unfinished (lit_intervals.comp.glsl,
// LOOP_LIMIT); each one sums at least one more interval of every such pixel or
// lowers its samples, so they end; max_passes only bounds a runaway.
void LitIntervalPass::resolve_in_passes(const SceneFrame& frame, const gpu::Program& program,
                                        const gpu::Texture& target) {
  constexpr int max_passes = 4096;
  glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindImageTexture(1, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  glBindImageTexture(2, progress_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  const GLuint zeros[2] = {0, 0};  // loop_limited, unfinished
  glNamedBufferSubData(node_count_.id(), 2 * sizeof(GLuint), sizeof(zeros), zeros);
  for (passes_ = 1;; ++passes_) {
    gpu::set_uniform(program, "resume", passes_ - 1);
    gpu::dispatch_pixels(frame.width(), frame.height());
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    GLuint counts[2] = {0, 0};
    glGetNamedBufferSubData(node_count_.id(), 2 * sizeof(GLuint), sizeof(counts), counts);
    loop_limited_ = counts[0];
    if (counts[1] == 0) break;
    if (passes_ == max_passes) {
      loop_limited_ += counts[1];
      break;
    }
    glNamedBufferSubData(node_count_.id(), 3 * sizeof(GLuint), sizeof(GLuint), &zeros[1]);
  }
  if (loop_limited_ > 0)
    warn("samples", std::to_string(loop_limited_) + " pixels' lit intervals were cut short by llvmpipe's limit of " +
                        std::to_string(gpu::software_loop_limit) +
                        " loop iterations per pixel, after " + std::to_string(passes_) +
                        " passes: too many crossings per view ray (a finer light volume, more casters in view)");
}

std::vector<std::pair<std::string, double>> LitIntervalPass::stats() const {
  return {{"crossings", static_cast<double>(crossings_)},
          {"fragments", fragments_},
          {"redraws", static_cast<double>(redraws_)},
          {"loop_limited", static_cast<double>(loop_limited_)},
          {"passes", static_cast<double>(passes_)}};
}

}  // namespace airlight::kit
