#pragma once
// OpenGL 4.5 core through libepoxy, with move-only RAII handles for GL objects.
#include <epoxy/gl.h>

#include <cstddef>
#include <utility>

namespace airlight::gpu {

// A GL object name that deletes itself; `Delete` frees one name.
template <void (*Delete)(GLuint)>
class Object {
public:
  Object() = default;
  explicit Object(GLuint id) : id_(id) {}
  Object(Object&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
  Object& operator=(Object&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, 0);
    }
    return *this;
  }
  Object(const Object&) = delete;
  Object& operator=(const Object&) = delete;
  ~Object() { reset(); }

  GLuint id() const { return id_; }
  explicit operator bool() const { return id_ != 0; }
  void reset() {
    if (id_) Delete(id_);
    id_ = 0;
  }

private:
  GLuint id_ = 0;
};

namespace detail {
// Buffers and textures also leave the allocation count (allocated_bytes).
void delete_buffer(GLuint id);
void delete_texture(GLuint id);
inline void delete_framebuffer(GLuint id) { glDeleteFramebuffers(1, &id); }
inline void delete_vertex_array(GLuint id) { glDeleteVertexArrays(1, &id); }
inline void delete_query(GLuint id) { glDeleteQueries(1, &id); }
inline void delete_sampler(GLuint id) { glDeleteSamplers(1, &id); }
inline void delete_program(GLuint id) { glDeleteProgram(id); }
inline void delete_shader(GLuint id) { glDeleteShader(id); }
}  // namespace detail

using Buffer = Object<detail::delete_buffer>;
using Texture = Object<detail::delete_texture>;
using Framebuffer = Object<detail::delete_framebuffer>;
using VertexArray = Object<detail::delete_vertex_array>;
using Query = Object<detail::delete_query>;
using Sampler = Object<detail::delete_sampler>;
using Program = Object<detail::delete_program>;
using Shader = Object<detail::delete_shader>;

// Whether the context is Mesa's llvmpipe: its timer queries miss compute work,
// and it ends an invocation's loops after LP_MAX_TGSI_LOOP_ITERATIONS (65535)
// iterations summed over them all (docs/decisions.md, Numerics).
bool software_renderer();
inline constexpr int software_loop_limit = 65535;

// The largest buffer and texture airlight makes. No GL query tells them: Mesa
// keeps a buffer's size in 32 bits, and llvmpipe refuses a texture of 2 GiB or
// more (docs/decisions.md "Memory for settings"). Past them make_buffer and
// make_texture throw OutOfMemory instead of leaving an object without storage.
inline constexpr double max_buffer_bytes = 4294967295.0;
inline constexpr double max_texture_bytes = 2147483648.0;

// Immutable-storage buffer of `bytes`, filled from `data` (or left for glNamedBufferSubData).
Buffer make_buffer(size_t bytes, const void* data, GLbitfield flags = GL_DYNAMIC_STORAGE_BIT);
// A 2D (or cube, 2D array, …) texture with immutable storage and nearest/clamp sampling.
Texture make_texture(GLenum target, GLenum internal_format, int width, int height, int layers = 1);
Framebuffer make_framebuffer();
VertexArray make_vertex_array();
Query make_query(GLenum target);
// Clamped, no depth comparison, filtered by `filter` (GL_NEAREST, GL_LINEAR):
// bound to a unit, it reads a texture's stored values whatever the texture's own
// parameters (a caller's shadow map).
Sampler make_sampler(GLenum filter);
inline Sampler make_nearest_sampler() { return make_sampler(GL_NEAREST); }

// Bytes of storage held by the live buffers and textures made above (texel size
// × width × height × layers), for `airlight bench`: what a method allocates is the
// difference across its prepare and first frame.
size_t allocated_bytes();

}  // namespace airlight::gpu
