#include "app/floor.hpp"

#include "gpu/context.hpp"
#include "gpu/gl.hpp"
#include "gpu/program.hpp"
#include "gpu/timer.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <vector>

namespace airlight::app {
namespace {

// Seconds of one dispatch of `program` over width × height, median of `frames` after `warmup`.
double time_program(const gpu::Program& program, int width, int height, int warmup, int frames) {
  std::vector<double> seconds;
  glUseProgram(program.id());
  for (int f = 0; f < warmup + frames; ++f) {
    gpu::PassTimer timer;
    {
      gpu::ScopedPass pass(timer, "floor");
      gpu::dispatch_pixels(width, height);
    }
    if (f >= warmup) seconds.push_back(timer.results().front().seconds);
  }
  return median(seconds);
}

}  // namespace

FloorTimes time_floor(int width, int height, int warmup, int frames) {
  gpu::Context& context = gpu::Context::current();
  constexpr int map_size = 1024;
  const gpu::Texture map = gpu::make_texture(GL_TEXTURE_2D, GL_R32F, map_size, map_size);
  const float occluders_far = 8.0f;  // some samples lit, some shadowed: the lookup is real work
  glClearTexImage(map.id(), 0, GL_RED, GL_FLOAT, &occluders_far);
  const gpu::Texture target = gpu::make_texture(GL_TEXTURE_2D, GL_RGBA32F, width, height);
  glBindTextureUnit(0, map.id());
  glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  const glm::mat4 light = glm::perspective(glm::radians(60.0f), 1.0f, 0.05f, 40.0f) *
                          glm::lookAt(glm::vec3(0, 3, -6), glm::vec3(0, 0, -6), glm::vec3(0, 0, 1));
  const gpu::Program& march = gpu::cached_compute_program("app/floor.comp.glsl");
  gpu::set_uniform(march, "steps", floor_steps);
  gpu::set_uniform(march, "light_matrix", light);
  FloorTimes t;
  t.fullscreen_s = time_program(gpu::cached_compute_program("app/floor.comp.glsl", "#define FULLSCREEN\n"), width,
                                height, warmup, frames);
  t.march_s = time_program(march, width, height, warmup, frames);
  t.ns_per_sample = t.march_s / (static_cast<double>(width) * height * floor_steps) * 1e9;
  context.check("floor");
  return t;
}

}  // namespace airlight::app
