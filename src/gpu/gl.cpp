#include "gpu/gl.hpp"

namespace airlight::gpu {

Buffer make_buffer(size_t bytes, const void* data, GLbitfield flags) {
  GLuint id = 0;
  glCreateBuffers(1, &id);
  // Zero-sized storage is an error in GL; one byte keeps empty arrays bindable.
  glNamedBufferStorage(id, bytes ? static_cast<GLsizeiptr>(bytes) : 1, bytes ? data : nullptr, flags);
  return Buffer(id);
}

Texture make_texture(GLenum target, GLenum internal_format, int width, int height, int layers) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  if (target == GL_TEXTURE_2D_ARRAY || target == GL_TEXTURE_CUBE_MAP_ARRAY)
    glTextureStorage3D(id, 1, internal_format, width, height, layers);
  else
    glTextureStorage2D(id, 1, internal_format, width, height);
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  return Texture(id);
}

Framebuffer make_framebuffer() {
  GLuint id = 0;
  glCreateFramebuffers(1, &id);
  return Framebuffer(id);
}

VertexArray make_vertex_array() {
  GLuint id = 0;
  glCreateVertexArrays(1, &id);
  return VertexArray(id);
}

Query make_query(GLenum target) {
  GLuint id = 0;
  glCreateQueries(target, 1, &id);
  return Query(id);
}

}  // namespace airlight::gpu
