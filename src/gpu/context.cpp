#include "gpu/context.hpp"

#include "gpu/gl.hpp"

#include <airlight/error.hpp>
#include <algorithm>

namespace airlight::gpu {

namespace {

const char* const install_hint =
    "no OpenGL 4.5 core context could be created through EGL. Install Mesa's EGL and drivers "
    "(Debian: apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri) or a GPU driver that provides "
    "EGL with OpenGL 4.5";

bool has_extension(const char* list, const std::string& name) {
  return list && (" " + std::string(list) + " ").find(" " + name + " ") != std::string::npos;
}

EGLDisplay initialize(EGLDisplay display) {
  if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  return EGL_NO_DISPLAY;
}

EGLDisplay surfaceless_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_MESA_platform_surfaceless")) return EGL_NO_DISPLAY;
  return initialize(eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr));
}

EGLDisplay device_display() {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client, "EGL_EXT_platform_device")) return EGL_NO_DISPLAY;
  EGLDeviceEXT devices[16];
  EGLint count = 0;
  if (!eglQueryDevicesEXT(16, devices, &count)) return EGL_NO_DISPLAY;
  for (EGLint i = 0; i < count; ++i)
    if (EGLDisplay d = initialize(eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr)))
      return d;
  return EGL_NO_DISPLAY;
}

EGLContext create_context(EGLDisplay display, EGLContext share = EGL_NO_CONTEXT) {
  if (!eglBindAPI(EGL_OPENGL_API)) return EGL_NO_CONTEXT;
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION, 4,
                               EGL_CONTEXT_MINOR_VERSION, 5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                               EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE,
                               EGL_NONE};
  // No config: the context renders only into framebuffer objects (EGL_KHR_no_config_context).
  return eglCreateContext(display, EGL_NO_CONFIG_KHR, share, attributes);
}

}  // namespace

Context& Context::headless() {
  // Never destroyed: tearing EGL down from a static destructor races Mesa's own
  // exit handlers, and the process is ending anyway.
  static Context* context = new Context();
  return *context;
}

namespace {
Context* adopted = nullptr;
}  // namespace

Context& Context::current() { return adopted ? *adopted : headless(); }

void Context::adopt_current() {
  if (adopted) return;
  adopted = new Context(Adopted{});  // never destroyed, as headless()
}

Context::Context(Adopted) : owned_(false) {
  const GLubyte* renderer = glGetString(GL_RENDERER);
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (!renderer || major * 10 + minor < 45)
    throw Failure("use_current_gl_context: no OpenGL 4.5 context is current on this thread (found " +
                  (renderer ? std::to_string(major) + "." + std::to_string(minor) : std::string("none")) + ")");
  renderer_ = reinterpret_cast<const char*>(renderer);
  query_limits();
  while (glGetError() != GL_NO_ERROR) {
  }  // the caller's earlier errors are not airlight's
}

Context::Context() {
  display_ = surfaceless_display();
  if (display_ == EGL_NO_DISPLAY) display_ = device_display();
  if (display_ == EGL_NO_DISPLAY) throw Failure(install_hint);
  context_ = create_context(display_);
  if (context_ == EGL_NO_CONTEXT || !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    eglTerminate(display_);
    throw Failure(install_hint);
  }
  renderer_ = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  query_limits();
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // the message arrives inside the call that caused it
  glDebugMessageCallback(debug_callback, this);
}

Context::Worker Context::worker() {
  if (!owned_) return given_;
  if (worker_ == EGL_NO_CONTEXT) worker_ = create_context(display_, context_);
  if (worker_ == EGL_NO_CONTEXT) return {};
  return {[display = display_, worker = worker_] { eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, worker); },
          [display = display_] { eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }};
}

void Context::give_worker(Worker worker) { given_ = std::move(worker); }

Context::~Context() {
  if (!owned_) return;
  if (worker_ != EGL_NO_CONTEXT) eglDestroyContext(display_, worker_);
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display_, context_);
  eglTerminate(display_);
}

void Context::debug_callback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                             const void* self) {
  // Errors and undefined behaviour fail; performance hints and notifications do not.
  if (type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR || severity == GL_DEBUG_SEVERITY_HIGH)
    const_cast<Context*>(static_cast<const Context*>(self))->errors_.push_back(message);
}

// The smallest of the limits a frame's targets meet: each is a texture attached
// to a framebuffer and drawn through a viewport.
void Context::query_limits() {
  GLint texture = 0, width = 0, height = 0, viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &width);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_HEIGHT, &height);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  auto smallest = [texture](GLint framebuffer, const char* framebuffer_name, GLint view, const char* view_name) {
    Limit limit{texture, "GL_MAX_TEXTURE_SIZE"};
    if (framebuffer < limit.side) limit = {framebuffer, framebuffer_name};
    if (view < limit.side) limit = {view, view_name};
    return limit;
  };
  width_limit_ = smallest(width, "GL_MAX_FRAMEBUFFER_WIDTH", viewport[0], "GL_MAX_VIEWPORT_DIMS");
  height_limit_ = smallest(height, "GL_MAX_FRAMEBUFFER_HEIGHT", viewport[1], "GL_MAX_VIEWPORT_DIMS");
}

void Context::check_frame_size(int width, int height) const {
  for (const auto& [side, limit] : {std::pair{width, width_limit_}, std::pair{height, height_limit_}})
    if (side > limit.side)
      throw InputError("frame", "size",
                       std::to_string(width) + "x" + std::to_string(height) + " exceeds this OpenGL implementation's " +
                           std::to_string(limit.side) + " pixels per side (" + limit.name + ", " + renderer_ + ")");
}

void Context::check(const std::string& where) {
  if (!owned_)
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
      errors_.push_back(e == GL_OUT_OF_MEMORY ? "GL_OUT_OF_MEMORY" : "GL error " + std::to_string(e));
  if (errors_.empty()) return;
  const bool memory = std::any_of(errors_.begin(), errors_.end(),
                                  [](const std::string& e) { return e.find("GL_OUT_OF_MEMORY") != std::string::npos; });
  std::string text = memory ? "out of memory (GL_OUT_OF_MEMORY) in " + where + ":" : "OpenGL error in " + where + ":";
  for (const auto& e : errors_) text += "\n  " + e;
  errors_.clear();
  if (memory) throw OutOfMemory(text);
  throw Failure(text);
}

}  // namespace airlight::gpu
