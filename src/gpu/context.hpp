#pragma once
// A headless OpenGL 4.5 core context from EGL: Mesa's surfaceless platform first,
// then the device platform (a real GPU without a display server). The same code
// runs on llvmpipe and on hardware. GL debug output is collected so that any GL
// error becomes a Failure (and so a test failure) at the next check().
#include <epoxy/egl.h>

#include <functional>
#include <string>
#include <vector>

namespace airlight::gpu {

class Context {
public:
  // The process's context, created and made current on first use. Throws
  // airlight::Failure saying what to install when no GL 4.5 core context exists.
  static Context& headless();
  // The context GPU work runs in: the caller's once adopt_current() was called,
  // else headless().
  static Context& current();
  // From now on current() is the GL context current on this thread (an
  // engine's). Throws Failure when none is current or it is older than 4.5.
  static void adopt_current();

  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;
  ~Context();

  const std::string& renderer() const { return renderer_; }

  // How a worker thread that links programs ahead (program.hpp's link_ahead)
  // makes a context sharing this one's objects current (`bind`), and lets it
  // go before it ends (`release`). An empty `bind`: there is none, as for an
  // adopted context whose owner gave none (give_worker). The headless
  // context's shared context is created on the first call, which must come
  // from this context's thread.
  struct Worker {
    std::function<void()> bind, release;
  };
  Worker worker();
  // An adopted context's worker: the owner of the windowing system (the
  // viewer) creates a context sharing this one's objects; it keeps it until
  // gpu::stop_linking() has returned. An empty Worker takes it back.
  void give_worker(Worker worker);

  // Throws InputError("frame", "size") when a frame of width × height cannot be
  // one framebuffer of this implementation: beyond its texture, framebuffer or
  // viewport limit, queried once (glGet), so a size is refused before anything
  // is allocated instead of failing as an incomplete framebuffer.
  void check_frame_size(int width, int height) const;

  // Throws Failure listing the GL errors reported since the last check; `where`
  // names the pass that was running.
  void check(const std::string& where);

private:
  struct Adopted {};
  Context();
  explicit Context(Adopted);
  static void debug_callback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message,
                             const void* self);
  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  EGLContext worker_ = EGL_NO_CONTEXT;
  Worker given_;  // an adopted context's (give_worker)
  std::string renderer_;
  struct Limit {
    int side;
    const char* name;
  };
  Limit width_limit_{}, height_limit_{};
  void query_limits();
  std::vector<std::string> errors_;
  bool owned_ = true;  // false: the caller's context, whose debug output stays the caller's
};

}  // namespace airlight::gpu
