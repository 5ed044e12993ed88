#include "methods/kit/counting/lit_interval_pass.hpp"

#include "core/warning.hpp"
#include "gpu/program.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cstdio>

namespace airlight::kit {
namespace {

constexpr GLuint end_of_list = 0xffffffffu;
constexpr size_t node_bytes = 3 * sizeof(GLuint);

constexpr const char* resolve_program = "methods/kit/counting/lit_intervals.comp.glsl";
constexpr const char* crossings_vertex = "methods/kit/counting/crossings.vert.glsl";
constexpr const char* crossings_fragment = "methods/kit/counting/crossings.frag.glsl";

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

LitIntervalPass::LitIntervalPass(const Settings& s, bool eye_planes)
    : capacity_per_pixel_(s.real("capacity")), samples_(s.integer("samples")), eye_planes_(eye_planes) {}

void LitIntervalPass::prepare() {
  counted_draw_.prepare();
  loop_limit_ = gpu::software_renderer();
  node_count_ = gpu::make_buffer(4 * sizeof(GLuint), nullptr);  // CountBlock
}

std::string LitIntervalPass::defines() const {
  std::string d = lit_interval_defines() + "#define SAMPLES " + std::to_string(samples_) + "\n";
  if (loop_limit_) d += "#define LOOP_LIMIT " + std::to_string(gpu::software_loop_limit) + "\n";
  if (eye_planes_) d += "#define EYE_PLANES\n";
  return d;
}

// The resolve's program's: the frame's and the pass's; the crossings' draw's, with the counted draw's.
std::string LitIntervalPass::resolve_defines(const SceneFrame& frame) const { return frame.defines() + defines(); }
std::string LitIntervalPass::crossings_defines(const SceneFrame& frame) const {
  return resolve_defines(frame) + CountedDraw::defines();
}

// The crossings' draw and the resolve, which every frame uses (the cull only
// when there are triangles, known after the frame's build); the resolve warmed
// on the worker, with this frame's lists and target, while the frame's geometry
// is built and drawn.
void LitIntervalPass::link_ahead(const SceneFrame& frame, const gpu::Texture& target) {
  gpu::link_ahead({{GL_VERTEX_SHADER, crossings_vertex}, {GL_FRAGMENT_SHADER, crossings_fragment}},
                  crossings_defines(frame));
  size_for(frame);
  gpu::link_compute_ahead(resolve_program, resolve_defines(frame),
                          frame.warm_pixels([images = resolve_images(target)] { images.bind(); }));
}

// The lists' heads (and progress) at the G-buffer's size, and the pool.
void LitIntervalPass::size_for(const SceneFrame& frame) {
  if (frame.gbuffer_width() != width_ || frame.gbuffer_height() != height_) {
    width_ = frame.gbuffer_width();
    height_ = frame.gbuffer_height();
    heads_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32UI, width_, height_);
    if (loop_limit_) progress_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32UI, width_, height_);
  }
  if (nodes_.id() == 0)
    allocate_pool(std::max<size_t>(static_cast<size_t>(double(width_) * height_ * capacity_per_pixel_), 1));
}

// The images the resolve reads and writes: the target, the lists' heads (the
// first pass sorts them) and, in passes, each pixel's progress.
LitIntervalPass::ResolveImages LitIntervalPass::resolve_images(const gpu::Texture& target) const {
  return {target.id(), heads_.id(), loop_limit_ ? progress_.id() : 0};
}

void LitIntervalPass::ResolveImages::bind() const {
  // In passes the first sorts the lists and later ones add to the target.
  glBindImageTexture(0, target, 0, GL_FALSE, 0, progress ? GL_READ_WRITE : GL_WRITE_ONLY, GL_RGBA32F);
  glBindImageTexture(1, heads, 0, GL_FALSE, 0, progress ? GL_READ_WRITE : GL_READ_ONLY, GL_R32UI);
  if (progress) glBindImageTexture(2, progress, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
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
    if (!triangles.on_gpu) triangles_.assign(triangles.on_cpu);
    list_crossings(frame, triangles.on_gpu ? *triangles.on_gpu : triangles_.buffer(), triangles.size());
  }
  gpu::ScopedPass pass(timer, "airlight");
  const gpu::Program& program = gpu::cached_compute_program(resolve_program, resolve_defines(frame));
  frame.run_where_warmed(program, [&] { resolve(frame, program, eye, target); });
}

// Every pixel's list of crossings, the pool grown and the triangles drawn
// again until every crossing fits.
void LitIntervalPass::list_crossings(const SceneFrame& frame, const gpu::Buffer& triangles, size_t triangle_count) {
  size_for(frame);
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
      {{GL_VERTEX_SHADER, crossings_vertex}, {GL_FRAGMENT_SHADER, crossings_fragment}}, crossings_defines(frame));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, nodes_binding, nodes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, node_count_binding, node_count_.id());
  glBindImageTexture(0, heads_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
  counted_draw_.draw(frame, program, triangles, triangle_count);
  if (triangle_count > 0) glGetNamedBufferSubData(node_count_.id(), 0, sizeof(GLuint), &crossings_);
}

void LitIntervalPass::resolve(const SceneFrame& frame, const gpu::Program& program, const EyeCounts& eye,
                              const gpu::Texture& target) {
  glUseProgram(program.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, nodes_binding, nodes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, node_count_binding, node_count_.id());
  gpu::set_uniform(program, "eye_counts", eye.counts);
  if (!eye_planes_ && !eye.planes.empty()) throw Failure("lit intervals: planes through the eye from a geometry without them");
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
  resolve_images(target).bind();
  loop_limited_ = 0;
  passes_ = 1;
  if (!loop_limit_) {
    frame.dispatch_pixels();
    return;
  }
  resolve_in_passes(frame, program);
}

// llvmpipe: passes while some pixel is unfinished (lit_intervals.comp.glsl,
// LOOP_LIMIT); each one sums at least one more interval of every such pixel or
// lowers its samples, so they end; max_passes only bounds a runaway.
void LitIntervalPass::resolve_in_passes(const SceneFrame& frame, const gpu::Program& program) {
  constexpr int max_passes = 4096;
  const GLuint zeros[2] = {0, 0};  // loop_limited, unfinished
  glNamedBufferSubData(node_count_.id(), 2 * sizeof(GLuint), sizeof(zeros), zeros);
  for (passes_ = 1;; ++passes_) {
    gpu::set_uniform(program, "resume", passes_ - 1);
    frame.dispatch_pixels();
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
          {"fragments", counted_draw_.fragments()},
          {"redraws", static_cast<double>(redraws_)},
          {"loop_limited", static_cast<double>(loop_limited_)},
          {"passes", static_cast<double>(passes_)}};
}

}  // namespace airlight::kit
