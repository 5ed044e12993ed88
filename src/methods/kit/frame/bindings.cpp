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

void SceneFrame::bind() const {
  glBindBufferBase(GL_UNIFORM_BUFFER, binding::frame_block, frame_block_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::lights, lights_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::volumes, volumes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::lobes, lobes_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::face_normals, face_normals_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::objects, objects_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding::pixel_list, grid_list_ ? grid_list_->id() : 0);
  glBindTextureUnit(binding::distance, distance().id());
  glBindTextureUnit(binding::normal, normal_.id());
  glBindTextureUnit(binding::geometric_normal, geometric_normal_.id());
  glBindTextureUnit(binding::albedo, albedo_.id());
  glBindTextureUnit(binding::gobos, gobos_.id());
  glBindTextureUnit(binding::shadow_maps, shadow_maps_.id());
  glBindTextureUnit(binding::shadow_cubes, shadow_cubes_.id());
  for (GLuint unit = 0; unit < binding::first_free_texture; ++unit) glBindSampler(unit, 0);
}

}  // namespace airlight::kit
