#include "methods/kit/frame/scene_frame.hpp"

#include "geometry/camera.hpp"
#include "gpu/program.hpp"
#include "methods/kit/frame/frame_data.hpp"
#include "methods/kit/frame/scene_frame_parts.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cstddef>

namespace airlight::kit {

using namespace gpu;

namespace {

// Gobos are uploaded at prepare: a frame may only use those.
void check_gobos(const FrameInputs& in, const std::vector<const Image*>& gobos) {
  for (size_t i = 0; i < in.lights.size(); ++i)
    if (has_gobo(in.lights[i]) && std::find(gobos.begin(), gobos.end(), in.lights[i].gobo.get()) == gobos.end())
      throw InputError("frame", "lights[" + std::to_string(i) + "].gobo",
                       "is not a gobo of the prepared scene's lights (gobos are uploaded at prepare)");
}

}  // namespace

void SceneFrame::prepare(const Scene& scene) {
  geometry::camera_basis(scene.camera);  // throws now for a degenerate camera
  scene_ = scene;
  upload_meshes(scene);
  upload_gobos(scene);
  frame_block_ = make_buffer(sizeof(shader::FrameData), nullptr);
  const shader::FrameData empty{};
  empty_block_ = make_buffer(sizeof empty, &empty);
  gbuffer_fbo_ = make_framebuffer();
  shadow_fbo_ = make_framebuffer();
  nearest_ = gpu::make_nearest_sampler();
  inputs_ = FrameInputs{};
  shadow_layout_ = {};
  shadow_resolution_ = 0;
}

void SceneFrame::render(const FrameInputs& inputs, const FrameSettings& settings, const EngineFrame* engine,
                        Needs needs, PassTimer& timer) {
  set_inputs(inputs, settings, engine, needs);
  render_passes(engine, needs, timer);
}

void SceneFrame::set_inputs(const FrameInputs& inputs, const FrameSettings& settings, const EngineFrame* engine,
                            Needs needs) {
  check_frame_inputs(scene_, inputs);
  check_gobos(inputs, gobo_images_);
  geometry::camera_basis(inputs.camera);  // throws for a degenerate camera
  resize(inputs.width, inputs.height);
  inputs_ = inputs;
  grid_distance_ = nullptr;
  grid_list_ = nullptr;
  grid_width_ = inputs.width;
  grid_height_ = inputs.height;
  upload_inputs(settings, engine, needs.shadows);
}

void SceneFrame::render_passes(const EngineFrame* engine, Needs needs, PassTimer& timer) {
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

void SceneFrame::use_grid(const Texture& distance, int width, int height, const Buffer* pixel_list) {
  grid_distance_ = &distance;
  grid_list_ = pixel_list;
  grid_width_ = width;
  grid_height_ = height;
  const glm::vec2 size(width, height);
  glNamedBufferSubData(frame_block_.id(), offsetof(shader::FrameData, size), sizeof size, &size);
  const int sparse = pixel_list ? 1 : 0;
  glNamedBufferSubData(frame_block_.id(), offsetof(shader::FrameData, sparse), sizeof sparse, &sparse);
}

void SceneFrame::dispatch_pixels() const {
  if (grid_list_)
    gpu::dispatch_indirect(*grid_list_);
  else
    gpu::dispatch_pixels(grid_width_, grid_height_);
}

void SceneFrame::use_gbuffer_grid(const Buffer* pixel_list) {
  use_grid(distance_, inputs_.width, inputs_.height, pixel_list);
  grid_distance_ = nullptr;
}

void SceneFrame::shade_surfaces() {
  glUseProgram(cached_compute_program("methods/kit/frame/surface.comp.glsl", defines_).id());
  glBindImageTexture(0, surface_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  gpu::dispatch_pixels(inputs_.width, inputs_.height);
}

}  // namespace airlight::kit
