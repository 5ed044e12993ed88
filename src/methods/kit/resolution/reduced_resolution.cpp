#include "methods/kit/resolution/reduced_resolution.hpp"

#include "gpu/program.hpp"
#include "geometry/camera.hpp"
#include "methods/kit/frame/bindings.hpp"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <string>

namespace airlight::kit {

using namespace gpu;

namespace {

enum class Upsample { bilateral, bilinear };  // the `upsample` setting's choices

constexpr GLuint first_texture = binding::first_free_texture;
constexpr GLuint counter_binding = binding::first_free_storage, light_images_binding = counter_binding + 1;
constexpr GLuint tile_flags_binding = light_images_binding + 1;
constexpr GLsizeiptr tile_header = 4 * sizeof(GLuint);  // tiles.glsl's tile_groups

// Pixels within this many coarse pixels of a light's image are recomputed:
// linear interpolation of L_air ∝ 1/h over a coarse pixel of D pixels errs by
// about (D/2h)², 1 % at h = 5·D (docs/decisions.md "Reduced resolution").
constexpr float near_light_coarse_pixels = 8.0f;

// The window coordinates (GL, pixels) of each point and spot light in front
// of the camera: view_ray.glsl's window_of on the CPU.
std::vector<glm::vec2> light_images(const FrameInputs& in) {
  const geometry::CameraBasis f = geometry::camera_basis(in.camera);
  const double aspect = double(in.width) / in.height;
  std::vector<glm::vec2> images;
  for (const Light& light : in.lights) {
    if (light.type == LightType::directional) continue;
    const glm::dvec3 offset = glm::dvec3(light.position) - f.position;
    const double depth = glm::dot(offset, f.forward);
    if (!(depth > 0.0)) continue;
    const glm::dvec2 ndc(glm::dot(offset, f.right) / aspect, glm::dot(offset, f.up));
    const glm::dvec2 window = (ndc / (depth * f.tan_half_fov_y) + 1.0) * 0.5 * glm::dvec2(in.width, in.height);
    if (std::isfinite(window.x) && std::isfinite(window.y)) images.emplace_back(window);
  }
  return images;
}

std::string define(const char* name, int value) { return "#define " + std::string(name) + " " + std::to_string(value) + "\n"; }

const Program& program(const std::string& name, const std::string& defines) {
  return cached_compute_program("methods/kit/resolution/" + name + ".comp.glsl",
                                binding_defines() + define("BINDING_RECOMPUTED", counter_binding) +
                                    define("BINDING_LIGHT_IMAGES", light_images_binding) +
                                    define("BINDING_TILE_FLAGS", tile_flags_binding) + defines);
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
  if (!settings_.bilateral) return;
  failed_ = make_texture(GL_TEXTURE_2D, GL_R32F, width, height);
  recompute_distance_ = make_texture(GL_TEXTURE_2D, GL_R32F, width, height);
  recomputed_ = make_texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
  if (!counter_) counter_ = make_buffer(sizeof(GLuint), nullptr);
  const GLsizeiptr tiles = GLsizeiptr((width + 7) / 8) * ((height + 7) / 8);
  tiles_ = make_buffer(tile_header + tiles * 2 * sizeof(GLuint), nullptr);
  tile_flags_ = make_buffer(tiles * sizeof(GLuint), nullptr);
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

bool ReducedResolution::upsample(SceneFrame& frame, const Texture& target, int halo, PassTimer& timer) {
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
  const GLuint zero = 0, no_tiles[4] = {0, 0, 0, 0};
  glClearNamedBufferData(counter_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glNamedBufferSubData(tiles_.id(), 0, sizeof no_tiles, no_tiles);
  glClearNamedBufferData(tile_flags_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::tiles, tiles_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, tile_flags_binding, tile_flags_.id());
  const Program& upsample = program("upsample", "#define BILATERAL\n" + define("HALO", halo) + upsample_defines());
  glUseProgram(upsample.id());
  set_uniform(upsample, "light_images", upload_light_images(frame));
  set_uniform(upsample, "near_light", near_light_coarse_pixels * settings_.divisor);
  glBindImageTexture(1, failed_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, counter_binding, counter_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, light_images_binding, light_images_.id());
  dispatch_pixels((width_ + 1) / 2, (height_ + 1) / 2);  // 2×2 pixels an invocation
  list_tiles(halo);
  frame.use_grid(halo > 0 ? recompute_distance_ : failed_, width_, height_, &tiles_);
  frame.bind();
  return true;
}

// The recomputation's grid, where the method's result reads a halo (with
// none, upsample wrote it), and its tiles' indirect dispatch.
void ReducedResolution::list_tiles(int halo) {
  if (halo > 0) {
    glUseProgram(program("recompute_grid", define("HALO", halo)).id());
    glBindTextureUnit(first_texture, failed_.id());
    glBindImageTexture(0, recompute_distance_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    dispatch_pixels(width_, height_);
  }
  glUseProgram(program("tile_groups", "").id());
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
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
  glBindTextureUnit(first_texture, failed_.id());
  glBindTextureUnit(first_texture + 1, recomputed_.id());
  glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::tiles, tiles_.id());
  dispatch_indirect(tiles_);
}

double ReducedResolution::recomputed_fraction() const {
  if (!counter_ || width_ == 0) return 0.0;
  GLuint count = 0;
  glGetNamedBufferSubData(counter_.id(), 0, sizeof count, &count);
  return static_cast<double>(count) / (static_cast<double>(width_) * height_);
}

}  // namespace airlight::kit
