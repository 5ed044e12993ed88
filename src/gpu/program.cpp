#include "gpu/program.hpp"

#include "gpu/context.hpp"
#include "gpu/shader_sources.hpp"

#include <airlight/error.hpp>

#include <glm/gtc/type_ptr.hpp>
#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <thread>
#include <vector>

namespace airlight::gpu {

namespace {

std::string_view embedded(const std::string& name, const std::string& included_from) {
  const auto& all = embedded_shaders();
  const auto it = all.find(name);
  if (it == all.end())
    throw Failure("unknown shader '" + name + "'" + (included_from.empty() ? "" : " included from " + included_from));
  return it->second;
}

// Appends `name` with its includes expanded, each file once. #line keeps the
// compiler's line numbers true to each file (its source-string number is the
// file's index in `order`, listed in compile errors).
void expand(const std::string& name, const std::string& from, std::set<std::string>& seen,
            std::vector<std::string>& order, std::string& out) {
  if (!seen.insert(name).second) return;
  order.push_back(name);
  const int file_index = static_cast<int>(order.size());
  static const std::regex include(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
  std::istringstream in{std::string(embedded(name, from))};
  std::string line;
  int number = 0;
  out += "#line 1 " + std::to_string(file_index) + "\n";
  while (std::getline(in, line)) {
    ++number;
    std::smatch match;
    if (std::regex_match(line, match, include)) {
      expand(match[1], name, seen, order, out);
      out += "#line " + std::to_string(number + 1) + " " + std::to_string(file_index) + "\n";
    } else {
      out += line + "\n";
    }
  }
}

std::string expand_with_order(const std::string& name, const std::string& defines, std::vector<std::string>& order) {
  std::set<std::string> seen;
  std::string body;
  expand(name, "", seen, order, body);
  return "#version 450 core\n" + defines + "\n" + body;
}

std::string file_list(const std::vector<std::string>& order) {
  std::string text;
  for (size_t i = 0; i < order.size(); ++i) text += "\n  source " + std::to_string(i + 1) + ": " + order[i];
  return text;
}

std::string info_log(GLuint object, bool program) {
  GLint length = 0;
  program ? glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length) : glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
  program ? glGetProgramInfoLog(object, length, nullptr, log.data())
          : glGetShaderInfoLog(object, length, nullptr, log.data());
  return log.c_str();
}

Shader compile(const Stage& stage, const std::string& defines) {
  std::vector<std::string> order;
  const std::string text = expand_with_order(stage.name, defines, order);
  Shader shader(glCreateShader(stage.type));
  const char* source = text.c_str();
  glShaderSource(shader.id(), 1, &source, nullptr);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (!ok) throw Failure("cannot compile shader " + stage.name + ":\n" + info_log(shader.id(), false) + file_list(order));
  return shader;
}

GLint location(const Program& p, const char* name) { return glGetUniformLocation(p.id(), name); }

}  // namespace

std::string expand_source(const std::string& name, const std::string& defines) {
  std::vector<std::string> order;
  return expand_with_order(name, defines, order);
}

namespace {

// The worker's context has no debug output (Context::check): its GL errors,
// as Failure naming `what`.
void throw_gl_errors(const std::string& what) {
  std::string errors;
  char code[16];
  for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError()) {
    std::snprintf(code, sizeof code, "0x%04x", e);
    errors += std::string(errors.empty() ? "" : ", ") + code;
  }
  if (!errors.empty()) throw Failure("GL error " + errors + " in " + what);
}

// Unbinds whatever a job bound in the worker's context: an object a binding
// there held would outlive its deletion in the caller's (a method's pools
// and targets, hundreds of megabytes).
void unbind_all() {
  GLint ssbos = 0, images = 0, textures = 0, ubos = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &ssbos);
  glGetIntegerv(GL_MAX_IMAGE_UNITS, &images);
  glGetIntegerv(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS, &textures);
  glGetIntegerv(GL_MAX_UNIFORM_BUFFER_BINDINGS, &ubos);
  glUseProgram(0);
  glBindBuffersBase(GL_SHADER_STORAGE_BUFFER, 0, ssbos, nullptr);
  glBindBuffersBase(GL_UNIFORM_BUFFER, 0, ubos, nullptr);
  glBindImageTextures(0, images, nullptr);
  glBindTextures(0, textures, nullptr);
  glBindSamplers(0, textures, nullptr);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
}

// Compiles `stages` and links them into `program`; throws Failure with the log.
void link_into(const Program& program, const std::vector<Stage>& stages, const std::string& defines) {
  std::vector<Shader> shaders;
  std::string names;
  for (const auto& stage : stages) {
    shaders.push_back(compile(stage, defines));
    glAttachShader(program.id(), shaders.back().id());
    names += (names.empty() ? "" : " + ") + stage.name;
  }
  glLinkProgram(program.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (!ok) throw Failure("cannot link program " + names + ":\n" + info_log(program.id(), true));
}

}  // namespace

Program make_program(std::initializer_list<Stage> stages, const std::string& defines) {
  Program program(glCreateProgram());
  link_into(program, {stages}, defines);
  return program;
}

Program make_compute_program(const std::string& name, const std::string& defines) {
  return make_program({{GL_COMPUTE_SHADER, name}}, defines);
}

void set_uniform(const Program& p, const char* name, int v) { glProgramUniform1i(p.id(), location(p, name), v); }
void set_uniform(const Program& p, const char* name, float v) { glProgramUniform1f(p.id(), location(p, name), v); }
void set_uniform(const Program& p, const char* name, const glm::vec2& v) {
  glProgramUniform2fv(p.id(), location(p, name), 1, glm::value_ptr(v));
}
void set_uniform(const Program& p, const char* name, const glm::vec3& v) {
  glProgramUniform3fv(p.id(), location(p, name), 1, glm::value_ptr(v));
}
void set_uniform(const Program& p, const char* name, const glm::vec4& v) {
  glProgramUniform4fv(p.id(), location(p, name), 1, glm::value_ptr(v));
}
void set_uniform(const Program& p, const char* name, const glm::mat4& v) {
  glProgramUniformMatrix4fv(p.id(), location(p, name), 1, GL_FALSE, glm::value_ptr(v));
}
void set_uniform(const Program& p, const char* name, const std::vector<glm::vec4>& v) {
  if (!v.empty()) glProgramUniform4fv(p.id(), location(p, name), static_cast<GLsizei>(v.size()), glm::value_ptr(v[0]));
}

void set_uniform(const Program& p, const char* name, const std::vector<int>& v) {
  if (!v.empty()) glProgramUniform1iv(p.id(), location(p, name), static_cast<GLsizei>(v.size()), v.data());
}

namespace {

std::map<std::string, Program>& program_cache() {
  static auto* cache = new std::map<std::string, Program>;  // never destroyed, as the context
  return *cache;
}

std::string program_key(std::initializer_list<Stage> stages, const std::string& defines) {
  std::string key = defines;
  for (const Stage& s : stages) key += "\n#stage " + std::to_string(s.type) + " " + s.name;
  return key;
}

// A program linked on the worker. A type of this file alone: the future's
// and the task's types built on it stay out of libairlight's exports.
struct Linked {
  Program program;
  bool warmed;
};
// What one job links, in order; cached_program moves each out when asked.
using Bundle = std::shared_ptr<std::vector<Linked>>;

struct ProgramSource {
  std::string key;
  std::vector<Stage> stages;
  std::string defines;
};

// One thread that compiles and links in a context sharing the caller's
// objects, and runs the jobs run_in_worker_context gives it there: links in
// order, and each run_in_worker_context job before the links not begun.
// llvmpipe spends about half of a large program's compile in the link (GLSL
// to NIR, docs/decisions.md); the other half, the machine code, it generates
// at the first dispatch for the context that dispatches: a program warmed
// here (Warm) is then dispatched here.
class Linker {
public:
  // The linker of the current context's worker, started on first use;
  // nullptr when the context has no worker. A linker of another context (the
  // headless one, before an engine's was adopted) is stopped: its programs
  // would be another share group's.
  static Linker* instance() {
    Context& context = Context::current();
    if (running() && running()->context_ != &context) stop();
    if (!running()) {
      Context::Worker worker = context.worker();
      if (!worker.bind) return nullptr;
      running() = new Linker(context, std::move(worker));
      // A frame that threw may leave a link running: the process's exit waits
      // for it rather than tear the driver down under it (Mesa's own exit
      // handlers, registered with the context before this, run after).
      static const int waits_at_exit = std::atexit(stop);
      (void)waits_at_exit;
    }
    return running();
  }

  // Ends the worker after what it was asked to link.
  static void stop() {
    delete running();
    running() = nullptr;
  }

  ~Linker() {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    ready_.notify_one();
    thread_.join();
  }

  // Links the programs in one job, each warmed right after its link.
  std::shared_future<Bundle> link(std::vector<ProgramSource> sources, Warm warm) {
    std::vector<std::string> keys;
    for (const ProgramSource& source : sources) keys.push_back(source.key);
    auto job = std::make_shared<std::packaged_task<Bundle()>>([sources = std::move(sources), warm = std::move(warm)] {
      auto bundle = std::make_shared<std::vector<Linked>>();
      for (const ProgramSource& source : sources) {
        Program program(glCreateProgram());
        link_into(program, source.stages, source.defines);
        if (warm) warm(program);
        // A warm-up only saves the first dispatch its code: one that failed
        // (its textures deleted meanwhile, by a frame that threw) leaves it
        // there, so its GL errors are dropped, not thrown into a later frame.
        while (glGetError() != GL_NO_ERROR) {
        }
        bundle->push_back({std::move(program), static_cast<bool>(warm)});
      }
      glFinish();  // the links are complete before another context uses the programs
      return bundle;
    });
    std::shared_future<Bundle> linked = job->get_future().share();
    queue(std::packaged_task<void()>([job] { (*job)(); }), std::move(keys));
    return linked;
  }

  // Takes back the job that links `key` if the worker has not begun it: the
  // keys of all it would have linked, whose future is then broken, never to
  // be asked for; none if it has begun.
  std::vector<std::string> take_back(const std::string& key) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto job = std::find_if(jobs_.begin(), jobs_.end(), [&](const Job& j) {
      return std::find(j.keys.begin(), j.keys.end(), key) != j.keys.end();
    });
    if (job == jobs_.end()) return {};
    std::vector<std::string> keys = std::move(job->keys);
    jobs_.erase(job);
    return keys;
  }

  bool on_its_thread() const { return std::this_thread::get_id() == thread_.get_id(); }

  // The running worker's jobs not begun (none if no worker runs: it starts none).
  static int waiting() {
    if (!running()) return 0;
    const std::lock_guard<std::mutex> lock(running()->mutex_);
    return static_cast<int>(running()->jobs_.size());
  }

  // `keys`: what a link job links, which take_back finds it by. A job
  // without (run_in_worker_context's) goes before the links not begun: it
  // uses programs the frame already has, and the frame waits for it.
  std::future<void> queue(std::packaged_task<void()> job, std::vector<std::string> keys = {}) {
    std::future<void> done = job.get_future();
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      const auto at = keys.empty() ? std::find_if(jobs_.begin(), jobs_.end(), [](const Job& j) { return !j.keys.empty(); })
                                   : jobs_.end();
      jobs_.insert(at, {std::move(keys), std::move(job)});
    }
    ready_.notify_one();
    return done;
  }

private:
  static Linker*& running() {
    static Linker* linker = nullptr;
    return linker;
  }

  Linker(const Context& context, Context::Worker worker)
      : context_(&context), thread_([this, worker = std::move(worker)] {
          worker.bind();
          for (;;) {
            std::unique_lock<std::mutex> lock(mutex_);
            ready_.wait(lock, [this] { return !jobs_.empty() || stopping_; });
            if (jobs_.empty()) break;
            std::packaged_task<void()> job = std::move(jobs_.front().task);
            jobs_.pop_front();
            lock.unlock();
            job();  // a compile or link error is the future's, thrown where the program is asked for
            unbind_all();
          }
          worker.release();
        }) {}

  const Context* context_;
  std::mutex mutex_;
  std::condition_variable ready_;
  struct Job {
    std::vector<std::string> keys;
    std::packaged_task<void()> task;
  };
  std::deque<Job> jobs_;
  bool stopping_ = false;
  std::thread thread_;  // last: it starts once everything it uses exists
};

// A program the Linker was asked to link (item `index` of its job's
// bundle), and its warm-up, which this thread runs on it in this context if
// it takes the job back.
struct Pending {
  std::shared_future<Bundle> linked;
  size_t index;
  Warm warm;
};

// Programs a Linker is linking, by key (this thread's, as the cache).
std::map<std::string, Pending>& linking() {
  static auto* pending = new std::map<std::string, Pending>;
  return *pending;
}

// Programs of a job taken back, not yet asked for: their warm-ups, run here
// when they are.
std::map<std::string, Warm>& taken_back_warms() {
  static auto* warms = new std::map<std::string, Warm>;
  return *warms;
}

// The programs the worker warmed, which run_where_warmed runs there.
std::set<GLuint>& warmed_on_worker() {
  static auto* warmed = new std::set<GLuint>;
  return *warmed;
}

int taken_ahead = 0;  // programs link_ahead queued that cached_program took, linked there or taken back
int taken_warmed = 0;  // of those, the ones warmed, there or here
int taken_back = 0;  // of those, the ones taken back before the worker began them

void count_taken(bool warmed) {
  ++taken_ahead;
  if (warmed) ++taken_warmed;
}

// What of `sources` is neither cached nor linking, in one job.
void link_ahead(std::vector<ProgramSource> sources, const Warm& warm) {
  std::erase_if(sources, [](const ProgramSource& source) {
    return program_cache().count(source.key) || linking().count(source.key) || taken_back_warms().count(source.key);
  });
  Linker* linker = Linker::instance();
  if (!linker || sources.empty()) return;
  std::vector<std::string> keys;
  for (const ProgramSource& source : sources) keys.push_back(source.key);
  const std::shared_future<Bundle> linked = linker->link(std::move(sources), warm);
  for (size_t k = 0; k < keys.size(); ++k) linking().emplace(keys[k], Pending{linked, k, warm});
}

ProgramSource compute_source(const std::string& name, const std::string& defines) {
  return {program_key({{GL_COMPUTE_SHADER, name}}, defines), {{GL_COMPUTE_SHADER, name}}, defines};
}

}  // namespace

void link_ahead(std::initializer_list<Stage> stages, const std::string& defines, Warm warm) {
  link_ahead({{program_key(stages, defines), stages, defines}}, warm);
}

void link_compute_ahead(const std::string& name, const std::string& defines, Warm warm) {
  link_ahead({compute_source(name, defines)}, warm);
}

void link_compute_ahead_together(const std::vector<std::pair<std::string, std::string>>& programs, Warm warm) {
  std::vector<ProgramSource> sources;
  for (const auto& [name, defines] : programs) sources.push_back(compute_source(name, defines));
  link_ahead(std::move(sources), warm);
}

void run_in_worker_context(const std::function<void()>& work) {
  Linker* linker = Linker::instance();
  if (!linker || linker->on_its_thread()) {  // none, or already there
    work();
    return;
  }
  // Server-side waits: on a GPU neither thread waits for the other's commands
  // to execute (llvmpipe waits on the CPU, where its commands run).
  GLsync before = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0), after = nullptr;
  glFlush();
  std::future<void> done = linker->queue(std::packaged_task<void()>([&] {
    glWaitSync(before, 0, GL_TIMEOUT_IGNORED);
    work();
    after = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    glFlush();
    throw_gl_errors("a pass in the worker's context");
  }));
  try {
    done.get();
  } catch (...) {
    glDeleteSync(before);
    if (after) glDeleteSync(after);
    throw;
  }
  glWaitSync(after, 0, GL_TIMEOUT_IGNORED);
  glDeleteSync(after);
  glDeleteSync(before);
}

void run_where_warmed(const Program& program, const std::function<void()>& work) {
  if (warmed_on_worker().count(program.id())) return run_in_worker_context(work);
  work();
}

const Program& cached_program(std::initializer_list<Stage> stages, const std::string& defines) {
  const std::string key = program_key(stages, defines);
  auto& cache = program_cache();
  auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  Linker* linker = Linker::instance();
  if (linker && linking().count(key))
    for (const std::string& k : linker->take_back(key)) {  // not begun: compiled here, beside the worker's job
      taken_back_warms().emplace(k, linking().at(k).warm);
      linking().erase(k);
    }
  const auto back = taken_back_warms().find(key);
  if (back != taken_back_warms().end()) {
    const Warm warm = std::move(back->second);
    taken_back_warms().erase(back);
    Program program = make_program(stages, defines);
    if (warm) warm(program);
    ++taken_back;
    count_taken(static_cast<bool>(warm));
    return cache.emplace(key, std::move(program)).first->second;
  }
  const auto found = linking().find(key);
  if (found == linking().end()) return cache.emplace(key, make_program(stages, defines)).first->second;
  Pending pending = std::move(found->second);
  linking().erase(found);
  Linked taken = std::move(pending.linked.get()->at(pending.index));  // get() throws the worker's compile or link error
  count_taken(taken.warmed);
  if (taken.warmed) warmed_on_worker().insert(taken.program.id());
  return cache.emplace(key, std::move(taken.program)).first->second;
}

const Program& cached_compute_program(const std::string& name, const std::string& defines) {
  return cached_program({{GL_COMPUTE_SHADER, name}}, defines);
}

int cached_program_count() { return static_cast<int>(program_cache().size()); }

int linked_ahead_count() { return taken_ahead; }

int warmed_count() { return taken_warmed; }

int taken_back_count() { return taken_back; }

int worker_jobs_waiting() { return Linker::waiting(); }

int programs_linking() { return static_cast<int>(linking().size() + taken_back_warms().size()); }

void stop_linking() { Linker::stop(); }

void clear_program_cache() {
  for (auto& [key, pending] : linking()) pending.linked.wait();  // deleted here, not while the worker links them
  linking().clear();
  taken_back_warms().clear();
  program_cache().clear();
  warmed_on_worker().clear();
}

void dispatch_pixels(int width, int height) {
  glDispatchCompute(static_cast<GLuint>((width + pixel_workgroup - 1) / pixel_workgroup),
                    static_cast<GLuint>((height + pixel_workgroup - 1) / pixel_workgroup), 1);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

void dispatch_indirect(const Buffer& counts) {
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, counts.id());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
}

Image read_image(const Texture& texture, int width, int height) {
  std::vector<glm::vec3> rows(static_cast<size_t>(width) * height);
  glGetTextureImage(texture.id(), 0, GL_RGB, GL_FLOAT, static_cast<GLsizei>(rows.size() * sizeof(glm::vec3)),
                    rows.data());
  Image image(width, height);
  for (int y = 0; y < height; ++y)  // GL row y is image row height − 1 − y
    std::copy_n(rows.begin() + static_cast<std::ptrdiff_t>(y) * width, width, &image.at(0, height - 1 - y));
  return image;
}

}  // namespace airlight::gpu
