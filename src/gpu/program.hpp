#pragma once
// GLSL programs from the embedded sources. A source may `#include "path.glsl"`
// (a path as embedded_shaders() keys it); each file is included once, so shared
// optics code needs no include guards. "#version 450 core" and the caller's
// defines are put in front.
#include "gpu/gl.hpp"

#include <airlight/image.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace airlight::gpu {

// The full text of an embedded shader with its includes expanded. Throws Failure
// naming the file for an unknown name or include.
std::string expand_source(const std::string& name, const std::string& defines = "");

struct Stage {
  GLenum type;       // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, …
  std::string name;  // embedded path
};

// Compiles and links; a compile or link error throws Failure with the log and the file.
Program make_program(std::initializer_list<Stage> stages, const std::string& defines = "");
Program make_compute_program(const std::string& name, const std::string& defines = "");

// The same, compiled on first use and kept for the process, keyed by the
// stages' names and the define set: a method asks for its program every frame
// and pays for compiling only when the define set is new. A program that
// link_ahead queued and the worker has not yet begun is taken back and
// compiled here, beside the worker's job, and warmed here with its Warm.
const Program& cached_program(std::initializer_list<Stage> stages, const std::string& defines = "");
const Program& cached_compute_program(const std::string& name, const std::string& defines = "");
// Starts compiling and linking a program that cached_program will be asked for
// later in this frame, on a worker thread with a context sharing this one's
// objects, so that the GLSL compiler runs beside the frame's earlier passes:
// cached_program then waits for it instead of linking. Without a worker (an
// engine's context) it does nothing and cached_program links as before. Only
// what a frame is sure to use belongs here: a program linked ahead and never
// asked for is never counted or freed until clear_program_cache.
//
// `warm`, when given, runs on the worker right after the link, in the
// worker's context: a dispatch there makes llvmpipe generate the program's
// machine code beside the frame's earlier passes, as the link is. That code
// is the worker context's alone (llvmpipe compiles per context), so a warmed
// program is then dispatched there, every frame (run_where_warmed).
using Warm = std::function<void(const Program&)>;
void link_ahead(std::initializer_list<Stage> stages, const std::string& defines = "", Warm warm = {});
void link_compute_ahead(const std::string& name, const std::string& defines = "", Warm warm = {});
// Compute programs (name, defines) linked and warmed by the worker in one job,
// and taken back together: a pass that dispatches them all runs in one place.
void link_compute_ahead_together(const std::vector<std::pair<std::string, std::string>>& programs, Warm warm);
// Runs `work` on the worker's thread in the worker's context, after the job
// it is on and the work it was given before, but before the links it has not
// begun (the frame waits for this; they are ahead of their use), and returns
// when it is done (rethrowing what it threw, and a GL error it raised as
// Failure). Fences order it after this context's commands so far and before
// the ones after. Without a worker, or called from the worker's own thread,
// runs it here.
void run_in_worker_context(const std::function<void()>& work);
// `work`, which dispatches `program`: in the worker's context if the worker
// warmed the program (link_ahead's Warm), else here.
void run_where_warmed(const Program& program, const std::function<void()>& work);
// Programs the cache has compiled so far in this process.
int cached_program_count();
// Of those, the ones link_ahead queued: linked by the worker, or taken back.
int linked_ahead_count();
// Of those, the ones warmed by link_ahead's Warm, on the worker or here.
int warmed_count();
// Of those, the ones cached_program took back before the worker began them.
int taken_back_count();
// The worker's jobs not begun: links and run_in_worker_context's.
int worker_jobs_waiting();
// Programs linked ahead that cached_program has not been asked for yet: 0
// after a frame that used everything it linked ahead.
int programs_linking();
// Ends link_ahead's worker thread once it has linked what it was asked to:
// before the context it binds (Context::give_worker) is destroyed. The next
// link_ahead starts another for the current context.
void stop_linking();
// Deletes every cached program (the context current, none of them in use): a
// long run over scenes of many structures would otherwise keep all their
// programs, hundreds of megabytes of llvmpipe's code per structure.
void clear_program_cache();

// Uniforms by name (a name the linker removed is ignored, as GL does).
void set_uniform(const Program& p, const char* name, int v);
void set_uniform(const Program& p, const char* name, float v);
void set_uniform(const Program& p, const char* name, const glm::vec2& v);
void set_uniform(const Program& p, const char* name, const glm::vec3& v);
void set_uniform(const Program& p, const char* name, const glm::vec4& v);
void set_uniform(const Program& p, const char* name, const glm::mat4& v);
// Array uniforms, elements 0 .. v.size() − 1.
void set_uniform(const Program& p, const char* name, const std::vector<glm::vec4>& v);
void set_uniform(const Program& p, const char* name, const std::vector<int>& v);

// local_size_x = local_size_y of every per-pixel compute program.
inline constexpr int pixel_workgroup = 8;

// Runs the bound compute program over width × height pixels in 8×8 workgroups
// (local_size_x = local_size_y = 8), then a memory barrier for what reads its output.
void dispatch_pixels(int width, int height);
// Runs the bound compute program over the workgroup counts at the start of
// `counts` (x, y, z: an indirect dispatch), then the same memory barrier.
void dispatch_indirect(const Buffer& counts);

// An RGBA32F (or R32F) texture's RGB as an Image, top row first (GL row y is
// image row height − 1 − y).
Image read_image(const Texture& texture, int width, int height);

}  // namespace airlight::gpu
