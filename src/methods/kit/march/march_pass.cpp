#include "methods/kit/march/march_pass.hpp"

#include "gpu/program.hpp"
#include "methods/kit/sampling/noise.hpp"

#include <algorithm>
#include <utility>

namespace airlight::kit {
namespace {

constexpr GLuint jitter_unit = kit::binding::first_free_texture;

// A pixel's own samples per dispatch; the march takes ceil(N / M² / that)
// dispatches, accumulating in the target. llvmpipe ends an invocation's loops
// after 65535 iterations counted over all its loops (gallivm
// LP_MAX_TGSI_LOOP_ITERATIONS), silently: with the per-light, per-lobe and
// per-volume loops inside each step, N = 4096 in one dispatch lost the end of
// the rays. 64 samples leave ~1000 inner iterations per sample, and keep each
// dispatch short for GPU watchdogs too. (Equiangular sampling marches each
// point or spot light separately: each sample index still evaluates each light
// once.) With interleaved's guard, a pixel beside a light's image marches every
// index of the dispatch's M² strides, so a dispatch spans at most 1024 indices.
int samples_per_dispatch(int block) { return std::max(1, std::min(64, 1024 / (block * block))); }

const std::vector<std::string> samplings{"uniform", "equiangular"};  // in Sampling's order

}  // namespace

std::vector<SettingSpec> march_settings() {
  using T = SettingSpec::Type;
  return {{"steps", T::integer, 64, 1, 4096, {},
           "samples N per view ray (per light with sampling=equiangular), at the middle of each step: the "
           "error falls as 1/N² where the integrand is smooth over a step, as 1/N across cone and shadow edges"},
          {"jitter", T::choice, 0, 0, 0, jitter_choices,
           "per-pixel offset of the samples within their steps (Kingston §5.1.1): none = the middle, "
           "white = hashed noise, blue = 64×64 void-and-cluster noise"},
          {"sampling", T::choice, 1, 0, 0, samplings,
           "where the steps go: equiangular (the default) = a march per point or spot light, even in the angle "
           "seen from the light (Kulla & Fajardo 2012), over the part of the ray inside a spot's cone: the 1/r² "
           "peak near a light is integrated exactly; uniform = even steps in distance (the documents')"}};
}

MarchSettings MarchSettings::from(const Settings& s, int block, bool normalized, bool guard) {
  return {s.integer("steps"), s.option<Jitter>("jitter"), s.option<Sampling>("sampling"), block, normalized, guard};
}

void MarchPass::prepare() {
  const std::vector<float> offsets = settings_.jitter == Jitter::blue ? blue_noise() : white_noise();
  noise_ = gpu::make_texture(GL_TEXTURE_2D, GL_R32F, noise_size, noise_size);
  glTextureSubImage2D(noise_.id(), 0, 0, 0, noise_size, noise_size, GL_RED, GL_FLOAT, offsets.data());
}

// The frame's defines and the march's settings as constants of its program (march.comp.glsl).
std::string MarchPass::defines(const kit::SceneFrame& frame) const {
  std::string d = frame.defines() + extra_defines_ + "#define BINDING_JITTER " + std::to_string(jitter_unit) + "\n";
  d += "#define SAMPLING " + std::to_string(static_cast<int>(settings_.sampling)) + "\n";
  if (settings_.jitter != Jitter::none) d += "#define JITTER\n";
  if (settings_.normalized) d += "#define NORMALIZED\n";
  if (settings_.guard) d += "#define GUARD\n";
  return d;
}

// The march warmed on the worker with this frame's textures, while the frame's
// other passes run.
void MarchPass::link_ahead(const kit::SceneFrame& frame, const gpu::Texture& target, std::function<void()> bind_own) {
  size_for(frame);
  gpu::link_compute_ahead(program_, defines(frame),
                          frame.warm_pixels([images = images(target), bind_own = std::move(bind_own)] {
                            images.bind();
                            if (bind_own) bind_own();
                          }));
}

void MarchPass::run(const kit::SceneFrame& frame, const gpu::Texture& target, const std::function<void()>& bind_own) {
  const int stride = settings_.block * settings_.block;
  const int own_samples = (settings_.steps + stride - 1) / stride;  // of pixel q = 0, the most
  size_for(frame);
  const gpu::Program& program = gpu::cached_compute_program(program_, defines(frame));
  frame.run_where_warmed(program, [&] {
    images(target).bind();
    if (bind_own) bind_own();
    glUseProgram(program.id());
    gpu::set_uniform(program, "steps", settings_.steps);
    gpu::set_uniform(program, "block", settings_.block);
    const int per_dispatch = samples_per_dispatch(settings_.block);
    for (int first = 0; first < own_samples; first += per_dispatch) {
      gpu::set_uniform(program, "first_sample", first);
      gpu::set_uniform(program, "sample_count", std::min(per_dispatch, own_samples - first));
      frame.dispatch_pixels();
    }
  });
  light_samples_ = static_cast<double>(frame.width()) * frame.height() * settings_.steps / stride * frame.light_count();
}

// The light guide and the spread at the G-buffer's size, as the settings ask.
void MarchPass::size_for(const kit::SceneFrame& frame) {
  if (frame.gbuffer_width() == width_ && frame.gbuffer_height() == height_) return;
  width_ = frame.gbuffer_width();
  height_ = frame.gbuffer_height();
  if (settings_.normalized) guide_ = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width_, height_);
  if (settings_.guard) spread_ = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width_, height_);
}

MarchPass::Images MarchPass::images(const gpu::Texture& target) const {
  return {target.id(), noise_.id(), guide_.id(), spread_.id()};
}

void MarchPass::Images::bind() const {
  glBindTextureUnit(jitter_unit, noise);
  glBindImageTexture(0, target, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  if (guide) glBindImageTexture(1, guide, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  if (spread) glBindImageTexture(2, spread, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
}

}  // namespace airlight::kit
