#pragma once
// A headless OpenGL 4.5 core context from EGL: Mesa's surfaceless platform first,
// then the device platform (a real GPU without a display server). The same code
// runs on llvmpipe and on hardware. GL debug output is collected so that any GL
// error becomes a Failure (and so a test failure) at the next check().
#include <epoxy/egl.h>

#include <string>
#include <vector>

namespace airlight::gpu {

class Context {
public:
  // The process's context, created and made current on first use. Throws
  // airlight::Failure saying what to install when no GL 4.5 core context exists.
  static Context& headless();

  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context();

  const std::string& renderer() const { return renderer_; }

  // Throws Failure listing the GL errors reported since the last check; `where`
  // names the pass that was running.
  void check(const std::string& where);

private:
  Context();
  static void debug_callback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                             const void* self);
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  std::string renderer_;
  std::vector<std::string> errors_;
};

}  // namespace airlight::gpu
