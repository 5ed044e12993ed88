#include "gpu/gl.hpp"

#include <airlight/error.hpp>

#include <cstdio>
#include <cstring>
#include <string>
#include <unordered_map>

namespace airlight::gpu {

namespace {

// Bytes per name; buffer and texture names are separate GL namespaces. GL calls
// come from the one thread that holds the context, so no lock.
struct Allocations {
  std::unordered_map<GLuint, size_t> buffers, textures;
  size_t total = 0;
  void add(std::unordered_map<GLuint, size_t>& names, GLuint id, size_t bytes) {
    names[id] = bytes;
    total += bytes;
  }
  void remove(std::unordered_map<GLuint, size_t>& names, GLuint id) {
    if (const auto it = names.find(id); it != names.end()) {
      total -= it->second;
      names.erase(it);
    }
  }
};

// Never destroyed: GL objects held by statics may be deleted after it otherwise.
Allocations& allocations() {
  static auto* all = new Allocations;
  return *all;
}

size_t texel_bytes(GLenum format) {
  switch (format) {
    case GL_R8: case GL_R8UI: return 1;
    case GL_RG8: case GL_R16F: case GL_DEPTH_COMPONENT16: return 2;
    case GL_RGBA8: case GL_SRGB8_ALPHA8: case GL_RG16F: case GL_R32F: case GL_R32I: case GL_R32UI:
    case GL_DEPTH_COMPONENT24: case GL_DEPTH_COMPONENT32F: case GL_DEPTH24_STENCIL8: return 4;
    case GL_RGBA16F: case GL_RG32F: case GL_DEPTH32F_STENCIL8: return 8;
    case GL_RGB32F: return 12;
    case GL_RGBA32F: case GL_RGBA32UI: return 16;
    default:  // a new format must be sized here, or bench would under-report memory
      throw Failure("make_texture: no texel size for internal format " + std::to_string(format));
  }
}

// The object sizes past the implementation's limit (gl.hpp), said as GL_OUT_OF_MEMORY is.
void check_object_size(double bytes, double limit, const char* object) {
  if (bytes < limit) return;
  char text[160];
  std::snprintf(text, sizeof text, "out of memory (GL_OUT_OF_MEMORY): one OpenGL %s of %.1f GiB, more than the %.0f GiB one %s holds on Mesa",
                object, bytes / 1073741824.0, limit / 1073741824.0, object);
  throw OutOfMemory(text);
}

}  // namespace

namespace detail {
void delete_buffer(GLuint id) {
  allocations().remove(allocations().buffers, id);
  glDeleteBuffers(1, &id);
}
void delete_texture(GLuint id) {
  allocations().remove(allocations().textures, id);
  glDeleteTextures(1, &id);
}
}  // namespace detail

Sampler make_sampler(GLenum filter) {
  GLuint id = 0;
  glCreateSamplers(1, &id);
  glSamplerParameteri(id, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(filter));
  glSamplerParameteri(id, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(filter));
  glSamplerParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(id, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  return Sampler(id);
}

size_t allocated_bytes() { return allocations().total; }

Buffer make_buffer(size_t bytes, const void* data, GLbitfield flags) {
  check_object_size(double(bytes), max_buffer_bytes + 1.0, "buffer");
  GLuint id = 0;
  glCreateBuffers(1, &id);
  // Zero-sized storage is an error in GL; one byte keeps empty arrays bindable.
  glNamedBufferStorage(id, bytes ? static_cast<GLsizeiptr>(bytes) : 1, bytes ? data : nullptr, flags);
  allocations().add(allocations().buffers, id, bytes ? bytes : 1);
  return Buffer(id);
}

Texture make_texture(GLenum target, GLenum internal_format, int width, int height, int layers) {
  const size_t texel = texel_bytes(internal_format);
  const size_t planes = target == GL_TEXTURE_CUBE_MAP ? 6 : (target == GL_TEXTURE_2D ? 1 : size_t(layers));
  const size_t bytes = texel * size_t(width) * size_t(height) * planes;
  check_object_size(double(bytes), max_texture_bytes, "texture");
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  if (target == GL_TEXTURE_2D_ARRAY || target == GL_TEXTURE_CUBE_MAP_ARRAY)
    glTextureStorage3D(id, 1, internal_format, width, height, layers);
  else
    glTextureStorage2D(id, 1, internal_format, width, height);
  allocations().add(allocations().textures, id, bytes);
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

bool software_renderer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer && std::strstr(renderer, "llvmpipe");
}

}  // namespace airlight::gpu
