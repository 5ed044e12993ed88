#include "methods/kit/resolution/reduced_resolution.hpp"

#include "gpu/program.hpp"
#include "geometry/camera.hpp"
#include "methods/kit/frame/bindings.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <optional>
#include <string>

namespace airlight::kit {

using namespace gpu;

namespace {

enum class Upsample { bilateral, bilinear };  // the `upsample` setting's choices

constexpr GLuint first_texture = binding::first_free_texture;
constexpr GLuint light_images_binding = binding::first_free_storage;
constexpr GLsizeiptr list_header = 4 * sizeof(GLuint);  // pixel_list.glsl's list_groups

// Pixels within this many coarse pixels of a light's image are recomputed:
// linear interpolation of L_air ∝ 1/h over a coarse pixel of D pixels errs by
// about (D/2h)², 1 % at h = 5·D (docs/decisions.md "Reduced resolution");
// and within at least as many pixels as at 1/4, where a gobo's stripes,
// converging on the light, are finer than a coarse pixel whatever its size
// ("Reduced resolution's second pass").
constexpr float near_light_coarse_pixels = 8.0f, near_light_min_pixels = 32.0f;

// The window coordinates (GL, pixels) of what lies at `offset` from the eye,
// if it is in front of the camera: view_ray.glsl's window_of on the CPU.
std::optional<glm::vec2> window_of(const FrameInputs& in, const geometry::CameraBasis& f, const glm::dvec3& offset) {
  const double depth = glm::dot(offset, f.forward);
  if (!(depth > 0.0)) return std::nullopt;
  const double aspect = double(in.width) / in.height;
  const glm::dvec2 ndc(glm::dot(offset, f.right) / aspect, glm::dot(offset, f.up));
  const glm::dvec2 window = (ndc / (depth * f.tan_half_fov_y) + 1.0) * 0.5 * glm::dvec2(in.width, in.height);
  if (!std::isfinite(window.x) || !std::isfinite(window.y)) return std::nullopt;
  return glm::vec2(window);
}

// Where L_air peaks in the image: each point and spot light in front of the
// camera (1/r² and the phase function peak there), and for a directional
// light the directions toward it and away from it, where view rays meet its
// light at 0° and 180°, the phase function's forward and backward peaks (a
// murky lobe's forward peak spans a few degrees; random scenes 32, 35, 38).
std::vector<glm::vec2> light_images(const FrameInputs& in) {
  const geometry::CameraBasis f = geometry::camera_basis(in.camera);
  std::vector<glm::dvec3> offsets;
  for (const Light& light : in.lights) {
    if (light.type != LightType::directional) {
      offsets.push_back(glm::dvec3(light.position) - f.position);
      continue;
    }
    const glm::dvec3 travel = glm::normalize(glm::dvec3(light.direction));
    offsets.push_back(-travel);
    offsets.push_back(travel);
  }
  std::vector<glm::vec2> images;
  for (const glm::dvec3& offset : offsets)
    if (const auto window = window_of(in, f, offset)) images.push_back(*window);
  return images;
}

// A pixel list (frame/pixel_list.glsl) with room for every pixel of the grid.
Buffer make_list(int width, int height) {
  return make_buffer(list_header + GLsizeiptr(width) * height * GLsizeiptr(sizeof(GLuint)), nullptr);
}

// Empties `list` and binds it, for a pass to append to.
void clear_list(const Buffer& list) {
  const GLuint empty[4] = {0, 0, 0, 0};
  glNamedBufferSubData(list.id(), 0, sizeof empty, empty);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::pixel_list, list.id());
}

std::string define(const char* name, int value) { return "#define " + std::string(name) + " " + std::to_string(value) + "\n"; }

const Program& program(const std::string& name, const std::string& defines) {
  return cached_compute_program("methods/kit/resolution/" + name + ".comp.glsl",
                                binding_defines() + define("BINDING_LIGHT_IMAGES", light_images_binding) + defines);
}

// The indirect dispatch's workgroups of the bound `list` once it is written.
void count_groups(const Buffer& list) {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::pixel_list, list.id());
  glUseProgram(program("list_groups", "").id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

}  // namespace

std::vector<SettingSpec> resolution_settings() {
  using T = SettingSpec::Type;
  return {{"scale", T::choice, 0, 0, 0, {"1", "1/2", "1/4"},
           "the airlight's grid per axis: 1/2 and 1/4 render it on a coarser grid (its distance the nearest "
           "and farthest of the G-buffer's, as a checkerboard) and bring it back by upsample"},
          {"upsample", T::choice, 0, 0, 0, {"bilateral", "bilinear"},
           "from a coarser scale: bilateral = joint bilateral upsampling guided by the full-resolution "
           "distance, the pixels it cannot place (every coarse neighbour across a depth edge, neighbours that "
           "disagree, a light's image near) recomputed at full scale (stat recomputed_fraction); bilinear = "
           "plain bilinear, nothing recomputed"}};
}

ResolutionSettings ResolutionSettings::from(const Settings& settings) {
  const auto& specs = settings.specs();
  if (std::none_of(specs.begin(), specs.end(), [](const SettingSpec& s) { return s.name == "scale"; })) return {};
  constexpr int divisors[] = {1, 2, 4};  // the `scale` setting's choices, in order
  return {divisors[settings.choice_index("scale")], settings.option<Upsample>("upsample") == Upsample::bilateral};
}

void ReducedResolution::allocate(const SceneFrame& frame) {
  const int width = frame.gbuffer_width(), height = frame.gbuffer_height();
  if (width == width_ && height == height_) return;
  width_ = width;
  height_ = height;
  coarse_width_ = (width + settings_.divisor - 1) / settings_.divisor;
  coarse_height_ = (height + settings_.divisor - 1) / settings_.divisor;
  coarse_distance_ = make_texture(GL_TEXTURE_2D, GL_R32F, coarse_width_, coarse_height_);
  coarse_airlight_ = make_texture(GL_TEXTURE_2D, GL_RGBA32F, coarse_width_, coarse_height_);
  failed_ = {};
  failed_blocks_ = {};
  halo_distance_ = {};
  halo_list_ = {};
  if (!settings_.bilateral) return;
  recomputed_ = make_texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
  failed_list_ = make_list(width, height);
}

void ReducedResolution::reduce(SceneFrame& frame, PassTimer& timer) {
  ScopedPass pass(timer, "downsample");
  allocate(frame);
  glUseProgram(program("downsample", define("DIVISOR", settings_.divisor)).id());
  glBindImageTexture(0, coarse_distance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  dispatch_pixels(coarse_width_, coarse_height_);
  frame.use_grid(coarse_distance_, coarse_width_, coarse_height_);
  frame.bind();
}

std::string ReducedResolution::upsample_defines() const {
  const bool exact = width_ % settings_.divisor == 0 && height_ % settings_.divisor == 0;
  return define("DIVISOR", settings_.divisor) + (exact ? "#define EXACT\n" : "");
}

bool ReducedResolution::upsample(SceneFrame& frame, const Texture& target, RecomputeGrid grid, PassTimer& timer) {
  ScopedPass pass(timer, "upsample");
  frame.use_gbuffer_grid();
  frame.bind();
  glUseProgram(program("stamp", "").id());
  glBindTextureUnit(first_texture, coarse_distance_.id());
  glBindImageTexture(0, coarse_airlight_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  dispatch_pixels(coarse_width_, coarse_height_);
  glBindTextureUnit(first_texture, coarse_airlight_.id());
  glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  if (!settings_.bilateral) {
    glUseProgram(program("upsample", upsample_defines()).id());
    dispatch_pixels((width_ + 1) / 2, (height_ + 1) / 2);  // 2×2 pixels an invocation
    return false;
  }
  bilateral_upsample(frame, grid);
  use_recompute_grid(frame, grid);
  return true;
}

// The bilateral upsampling proper: the failed pixels listed, and for the
// recomputation's grid their distance (marked, without a halo) or a flag a
// 2×2 block (to find a halo from). Each only where it is read: on llvmpipe a
// store a pixel is a good part of this pass.
void ReducedResolution::bilateral_upsample(const SceneFrame& frame, RecomputeGrid grid) {
  clear_list(failed_list_);
  const bool mark = grid.marked && grid.halo == 0, flag_blocks = grid.halo > 0;
  if (mark && !failed_) failed_ = make_texture(GL_TEXTURE_2D, GL_R32F, width_, height_);
  if (flag_blocks && !failed_blocks_)
    failed_blocks_ = make_texture(GL_TEXTURE_2D, GL_R32F, (width_ + 1) / 2, (height_ + 1) / 2);
  const Program& upsample = program("upsample", "#define BILATERAL\n" + upsample_defines() +
                                                    (mark ? "#define MARK\n" : "") +
                                                    (flag_blocks ? "#define FLAG_BLOCKS\n" : ""));
  glUseProgram(upsample.id());
  set_uniform(upsample, "light_images", upload_light_images(frame));
  set_uniform(upsample, "near_light", std::max(near_light_coarse_pixels * settings_.divisor, near_light_min_pixels));
  if (mark) glBindImageTexture(1, failed_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  if (flag_blocks) glBindImageTexture(2, failed_blocks_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, light_images_binding, light_images_.id());
  dispatch_pixels((width_ + 1) / 2, (height_ + 1) / 2);  // 2×2 pixels an invocation
  count_groups(failed_list_);
}

// The frame on the grid of the pixels to recompute: the failed ones, or with
// a halo those around them too (list_halo).
void ReducedResolution::use_recompute_grid(SceneFrame& frame, RecomputeGrid grid) {
  if (grid.halo > 0) list_halo(grid);
  const Buffer& list = grid.halo > 0 ? halo_list_ : failed_list_;
  if (grid.marked)
    frame.use_grid(grid.halo > 0 ? halo_distance_ : failed_, width_, height_, &list);
  else
    frame.use_gbuffer_grid(&list);
  frame.bind();
}

// The pixels to recompute where the method's result reads a halo around each
// failed pixel, listed, and for a marked grid their distance.
void ReducedResolution::list_halo(RecomputeGrid grid) {
  if (!halo_list_) halo_list_ = make_list(width_, height_);
  if (grid.marked && !halo_distance_) halo_distance_ = make_texture(GL_TEXTURE_2D, GL_R32F, width_, height_);
  clear_list(halo_list_);
  glUseProgram(program("recompute_grid", define("HALO", grid.halo) + (grid.marked ? "#define MARK\n" : "")).id());
  glBindTextureUnit(first_texture, failed_blocks_.id());
  if (grid.marked) glBindImageTexture(0, halo_distance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  dispatch_pixels((width_ + 1) / 2, (height_ + 1) / 2);  // 2×2 pixels an invocation
  count_groups(halo_list_);
}

int ReducedResolution::upload_light_images(const SceneFrame& frame) {
  const std::vector<glm::vec2> images = light_images(frame.inputs());
  light_images_.assign(images);
  return static_cast<int>(images.size());
}

void ReducedResolution::merge(SceneFrame& frame, const Texture& target, PassTimer& timer) {
  ScopedPass pass(timer, "merge");
  frame.use_gbuffer_grid();
  frame.bind();
  glUseProgram(program("merge", "").id());
  glBindTextureUnit(first_texture, recomputed_.id());
  glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::pixel_list, failed_list_.id());
  dispatch_indirect(failed_list_);
}

double ReducedResolution::recomputed_fraction() const {
  if (!failed_list_ || width_ == 0) return 0.0;
  GLuint count = 0;  // list_groups.w
  glGetNamedBufferSubData(failed_list_.id(), 3 * sizeof(GLuint), sizeof count, &count);
  return static_cast<double>(count) / (static_cast<double>(width_) * height_);
}

}  // namespace airlight::kit
