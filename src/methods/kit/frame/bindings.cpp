#include "methods/kit/frame/bindings.hpp"

#include "methods/kit/frame/scene_frame.hpp"

#include <utility>

namespace airlight::kit {

std::string binding_defines() {
  using namespace binding;
  const std::pair<const char*, GLuint> all[] = {
      {"FRAME_BLOCK", frame_block},   {"LIGHTS", lights},
      {"VOLUMES", volumes},           {"LOBES", lobes},
      {"FACE_NORMALS", face_normals}, {"OBJECTS", objects}, {"PIXEL_LIST", pixel_list},
      {"DISTANCE", distance},         {"NORMAL", normal},
      {"GEOMETRIC_NORMAL", geometric_normal}, {"ALBEDO", albedo},
      {"GOBOS", gobos},               {"SHADOW_MAPS", shadow_maps},
      {"SHADOW_CUBES", shadow_cubes}, {"ENGINE_INPUT", engine_input},
      {"FIRST_FREE_TEXTURE", first_free_texture}, {"FIRST_FREE_STORAGE", first_free_storage}};
  std::string text;
  for (const auto& [name, value] : all)
    text += "#define BINDING_" + std::string(name) + " " + std::to_string(value) + "\n";
  return text;
}

SceneFrame::Bindings SceneFrame::bindings() const {
  return {frame_block_.id(),     lights_.id(), volumes_.id(), lobes_.id(),  face_normals_.id(),
          objects_.id(),         grid_list_ ? grid_list_->id() : 0,         distance().id(),
          normal_.id(),          geometric_normal_.id(),                    albedo_.id(),
          gobos_.id(),           shadow_maps_.id(),                         shadow_cubes_.id()};
}

void SceneFrame::Bindings::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::frame_block, frame_block);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::lights, lights);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::volumes, volumes);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::lobes, lobes);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::face_normals, face_normals);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::objects, objects);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::pixel_list, pixel_list);
  glBindTextureUnit(binding::distance, distance);
  glBindTextureUnit(binding::normal, normal);
  glBindTextureUnit(binding::geometric_normal, geometric_normal);
  glBindTextureUnit(binding::albedo, albedo);
  glBindTextureUnit(binding::gobos, gobos);
  glBindTextureUnit(binding::shadow_maps, shadow_maps);
  glBindTextureUnit(binding::shadow_cubes, shadow_cubes);
  for (GLuint unit = 0; unit < binding::first_free_texture; ++unit) glBindSampler(unit, 0);
}

void SceneFrame::bind() const { bindings().bind(); }

gpu::Warm SceneFrame::warm_pixels(std::function<void()> bind_pass) const {
  return [frame = bindings(), empty = empty_block_.id(), bind_pass = std::move(bind_pass)](const gpu::Program& p) {
    frame.bind();
    bind_pass();
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::frame_block, empty);
    glUseProgram(p.id());
    glDispatchCompute(1, 1, 1);
    glUseProgram(0);
    glBindBufferBase(GL_UNIFORM_BUFFER, binding::frame_block, frame.frame_block);  // warmed here, the frame goes on
  };
}

void SceneFrame::run_where_warmed(const gpu::Program& program, const std::function<void()>& pass) const {
  gpu::run_where_warmed(program, [&] {
    bind();
    pass();
  });
}

}  // namespace airlight::kit
