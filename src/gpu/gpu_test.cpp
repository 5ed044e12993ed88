#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "gpu/query.hpp"
#include "gpu/timer.hpp"

#include <airlight/error.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <future>
#include <thread>
#include <vector>

namespace airlight::gpu {
namespace {

TEST(Gpu, HeadlessContextIsOpenGl45Core) {
  Context& context = Context::headless();
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 45);
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
  EXPECT_FALSE(context.renderer().empty());
  std::printf("renderer: %s\n", context.renderer().c_str());
}

// A frame one pixel wider than the implementation's smallest limit on a
// framebuffer's side is refused by name, before anything is allocated.
TEST(Gpu, FrameSizeBeyondTheImplementationsLimitIsRefusedByName) {
  Context& context = Context::headless();
  GLint texture = 0, framebuffer = 0, viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  glGetIntegerv(GL_MAX_FRAMEBUFFER_WIDTH, &framebuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  std::printf("max texture %d, framebuffer width %d, viewport %d\n", texture, framebuffer, viewport[0]);
  const int side = std::min({texture, framebuffer, viewport[0]});
  const char* name = side == texture ? "GL_MAX_TEXTURE_SIZE" : side == framebuffer ? "GL_MAX_FRAMEBUFFER_WIDTH"
                                                                                    : "GL_MAX_VIEWPORT_DIMS";
  EXPECT_NO_THROW(context.check_frame_size(side, 1));
  try {
    context.check_frame_size(side + 1, 1);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "frame: size: " + std::to_string(side + 1) + "x1 exceeds this OpenGL "
                                     "implementation's " + std::to_string(side) + " pixels per side (" + name +
                                     ", " + context.renderer() + ")");
  }
}

TEST(Gpu, ComputeProgramWithIncludesAndDefinesWritesABuffer) {
  Context& context = Context::headless();
  const Program program = make_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 0.5\n");
  constexpr int count = 100;
  const Buffer buffer = make_buffer(count * sizeof(float), nullptr);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
  glUseProgram(program.id());
  set_uniform(program, "count", count);
  PassTimer timer;
  timer.begin("fill");
  glDispatchCompute((count + 63) / 64, 1, 1);
  timer.end();
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> values(count);
  glGetNamedBufferSubData(buffer.id(), 0, count * sizeof(float), values.data());
  for (int i = 0; i < count; ++i) EXPECT_EQ(values[i], 0.5f * i * i);
  const auto times = timer.results();
  ASSERT_EQ(times.size(), 1u);
  EXPECT_EQ(times[0].pass, "fill");
  EXPECT_GE(times[0].seconds, 0.0);
  context.check("fill");
}

// The GPU's path (timestamp queries, forced on llvmpipe): frames end without
// a wait, ready() polls, giving the newest frame the GPU has written and never
// one older than it gave before; once the GPU is idle, the last frame; wait()
// is the one read that may wait, and is counted.
TEST(Gpu, PassTimerReadsFramesLaterWithoutWaiting) {
  Context& context = Context::headless();
  force_timestamp_queries(true);
  PassTimer timer;
  force_timestamp_queries(false);
  const Program program = make_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 0.5\n");
  const Buffer buffer = make_buffer(64 * sizeof(float), nullptr);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
  glUseProgram(program.id());
  set_uniform(program, "count", 64);
  EXPECT_EQ(timer.ready().frame, -1);  // no frame ended
  const std::int64_t waits = blocking_query_reads();
  std::int64_t newest = -1;
  constexpr int frames = 6;  // more than the 4 kept in flight: the oldest are dropped unread
  for (int frame = 0; frame < frames; ++frame) {
    {
      ScopedPass pass(timer, "fill");
      glDispatchCompute(1, 1, 1);
    }
    timer.end_frame();
    const FrameTimes ready = timer.ready();
    EXPECT_LE(ready.frame, frame);
    EXPECT_GE(ready.frame, newest);
    newest = ready.frame;
  }
  EXPECT_EQ(blocking_query_reads(), waits);
  glFinish();
  const FrameTimes idle = timer.ready();
  EXPECT_EQ(idle.frame, frames - 1);
  ASSERT_EQ(idle.times.size(), 1u);
  EXPECT_EQ(idle.times[0].pass, "fill");
  EXPECT_EQ(timer.wait().frame, frames - 1);  // nothing newer ended: the same frame, no query read
  EXPECT_EQ(blocking_query_reads(), waits);
  timer.begin("fill");
  timer.end();
  EXPECT_EQ(timer.results().size(), 1u);  // a one-shot measurement waits for its two timestamps
  EXPECT_EQ(blocking_query_reads(), waits + 2);
  context.check("timer frames");
}

// A draw's fragment count read without waiting is the count a blocking read
// of the same draw gives, frame after frame on the ring's queries, and
// reading it waits for nothing.
TEST(Gpu, InvocationCounterReadsWhatAWaitingReadWouldWithoutWaiting) {
  Context& context = Context::headless();
  if (!epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query")) GTEST_SKIP() << "no pipeline statistics";
  constexpr int width = 64, height = 32;
  const Texture target = make_texture(GL_TEXTURE_2D, GL_RGBA8, width, height);
  const Framebuffer fbo = make_framebuffer();
  glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  const VertexArray none = make_vertex_array();
  const Program program = make_program(
      {{GL_VERTEX_SHADER, "gpu/test_shaders/cover.vert.glsl"}, {GL_FRAGMENT_SHADER, "gpu/test_shaders/cover.frag.glsl"}});
  glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
  glViewport(0, 0, width, height);
  glBindVertexArray(none.id());
  glUseProgram(program.id());
  GLuint id = 0;
  glGenQueries(1, &id);  // Mesa's glCreateQueries refuses the statistics targets
  const Query waited(id);
  glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, waited.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
  const double expected = static_cast<double>(wait_query(waited));
  EXPECT_GE(expected, double(width * height));  // every pixel shaded at least once

  InvocationCounter counter;
  counter.prepare();
  EXPECT_FALSE(counter.latest());  // nothing counted yet
  const std::int64_t waits = blocking_query_reads();
  for (int frame = 0; frame < 6; ++frame) {  // more than the 4 counts kept in flight
    counter.begin();
    glDrawArrays(GL_TRIANGLES, 0, 3);
    counter.end();
    if (frame % 2 == 0) continue;  // two frames in flight before each read
    glFinish();
    ASSERT_TRUE(counter.latest());
    EXPECT_EQ(*counter.latest(), expected) << "frame " << frame;
  }
  EXPECT_EQ(blocking_query_reads(), waits);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  context.check("invocation counter");
}

// The cache compiles a define set once, and after clear_program_cache again.
TEST(Gpu, ProgramCacheCompilesOnceUntilCleared) {
  Context& context = Context::headless();
  const int before = cached_program_count();
  const GLuint first = cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 0.25\n").id();
  EXPECT_EQ(cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 0.25\n").id(), first);
  EXPECT_EQ(cached_program_count(), before + 1);
  clear_program_cache();
  EXPECT_EQ(cached_program_count(), 0);
  EXPECT_FALSE(glIsProgram(first)) << "deleted with the cache";
  cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 0.25\n");
  EXPECT_EQ(cached_program_count(), 1);
  context.check("program cache");
}

TEST(Gpu, IncludedFilesAppearOnce) {
  const std::string text = expand_source("gpu/test_shaders/fill.comp.glsl");
  EXPECT_EQ(text.rfind("#version 450 core\n", 0), 0u);
  const auto first = text.find("float square");
  ASSERT_NE(first, std::string::npos);
  EXPECT_EQ(text.find("float square", first + 1), std::string::npos);
}

template <typename F>
std::string failure_text(F&& f) {
  try {
    f();
  } catch (const Failure& e) {
    return e.what();
  }
  return "";
}

TEST(Gpu, CompileErrorsNameTheFile) {
  Context::headless();
  const std::string text = failure_text([] { make_compute_program("gpu/test_shaders/broken.comp.glsl"); });
  EXPECT_NE(text.find("cannot compile shader gpu/test_shaders/broken.comp.glsl"), std::string::npos) << text;
  EXPECT_NE(failure_text([] { expand_source("no/such.glsl"); }).find("unknown shader 'no/such.glsl'"), std::string::npos);
}

// What fill.comp.glsl writes with `program` bound, for 100 elements.
std::vector<float> fill(const Program& program) {
  constexpr int count = 100;
  const Buffer buffer = make_buffer(count * sizeof(float), nullptr);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer.id());
  glUseProgram(program.id());
  set_uniform(program, "count", count);
  glDispatchCompute((count + 63) / 64, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> values(count);
  glGetNamedBufferSubData(buffer.id(), 0, count * sizeof(float), values.data());
  return values;
}

// A program linked ahead on the headless context's worker is the one the
// cache then gives, counted once, and computes what the same program linked
// in place does; asking again links nothing.
TEST(Gpu, ProgramLinkedAheadOnTheWorkerIsTheCachedOne) {
  Context& context = Context::headless();
  const std::string defines = "#define SCALE 0.125\n";
  const int ahead = linked_ahead_count(), cached = cached_program_count();
  const int back = taken_back_count();
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", defines);
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", defines);  // once
  stop_linking();  // the worker links it before it ends: not taken back
  const Program& linked = cached_compute_program("gpu/test_shaders/fill.comp.glsl", defines);
  EXPECT_EQ(linked_ahead_count(), ahead + 1) << "the worker did not link it";
  EXPECT_EQ(taken_back_count(), back);
  EXPECT_EQ(cached_program_count(), cached + 1);
  EXPECT_EQ(fill(linked), fill(make_compute_program("gpu/test_shaders/fill.comp.glsl", defines)));
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", defines);  // already cached: nothing to link
  EXPECT_EQ(cached_compute_program("gpu/test_shaders/fill.comp.glsl", defines).id(), linked.id());
  EXPECT_EQ(linked_ahead_count(), ahead + 1);
  context.check("link ahead");
}

// A compile error on the worker is thrown where the program is asked for,
// with the same message as in place; clear_program_cache drops what is still
// being linked.
TEST(Gpu, CompileErrorsOnTheWorkerAreThrownWhereTheProgramIsAskedFor) {
  Context::headless();
  link_compute_ahead("gpu/test_shaders/broken.comp.glsl");
  const std::string text = failure_text([] { cached_compute_program("gpu/test_shaders/broken.comp.glsl"); });
  EXPECT_EQ(text, failure_text([] { make_compute_program("gpu/test_shaders/broken.comp.glsl"); }));
  EXPECT_NE(text.find("cannot compile shader gpu/test_shaders/broken.comp.glsl"), std::string::npos) << text;
  const int ahead = linked_ahead_count();
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", "#define SCALE 3.0\n");
  clear_program_cache();
  cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 3.0\n");
  EXPECT_EQ(linked_ahead_count(), ahead) << "cleared, it was linked again in place";
}

// A Warm runs on the worker right after the link, in the worker's context,
// with the program the cache then gives, and is counted when that is taken.
TEST(Gpu, WarmRunsOnTheWorkerWithTheLinkedProgram) {
  Context& context = Context::headless();
  const std::string defines = "#define SCALE 0.5\n";
  const int warmed = warmed_count();
  GLuint warmed_id = 0;
  std::thread::id warmed_on;
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", defines, [&](const Program& p) {
    warmed_id = p.id();  // read after cached_compute_program has waited for the link
    warmed_on = std::this_thread::get_id();
  });
  stop_linking();
  const Program& linked = cached_compute_program("gpu/test_shaders/fill.comp.glsl", defines);
  EXPECT_EQ(warmed_id, linked.id());
  EXPECT_NE(warmed_on, std::this_thread::get_id());
  EXPECT_EQ(warmed_count(), warmed + 1);
  context.check("warm");
}

// A warm-up that raises a GL error (textures deleted meanwhile) costs nothing
// but the warm-up: the program links and computes as ever, and no later call
// throws its error.
TEST(Gpu, AFailedWarmUpLeavesAWorkingProgram) {
  Context& context = Context::headless();
  const std::string defines = "#define SCALE 0.25\n";
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", defines,
                     [](const Program&) { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1u << 20, 0); });
  stop_linking();  // the warm-up on the worker, whose errors are dropped
  const Program& linked = cached_compute_program("gpu/test_shaders/fill.comp.glsl", defines);
  EXPECT_EQ(fill(linked)[4], 4.0f);  // 0.25·4²
  context.check("failed warm-up");
}

// A link the worker has not begun, queued behind a job that holds it, is
// taken back: compiled and warmed here, while the worker goes on; its pass
// then runs here, the worker's warmed one there (run_where_warmed).
TEST(Gpu, ALinkTheWorkerHasNotBegunIsTakenBackAndWarmedHere) {
  Context& context = Context::headless();
  const char* fill_program = "gpu/test_shaders/fill.comp.glsl";
  std::promise<void> started, release;
  std::shared_future<void> released = release.get_future().share();
  link_compute_ahead(fill_program, "#define SCALE 7.0\n", [&started, released](const Program&) {
    started.set_value();
    released.wait();
  });
  started.get_future().wait();  // the worker holds in the first warm-up
  std::thread::id warmed_on;
  link_compute_ahead(fill_program, "#define SCALE 8.0\n", [&](const Program&) { warmed_on = std::this_thread::get_id(); });
  const int ahead = linked_ahead_count(), warmed = warmed_count(), back = taken_back_count();
  const Program& second = cached_compute_program(fill_program, "#define SCALE 8.0\n");
  EXPECT_EQ(warmed_on, std::this_thread::get_id());
  EXPECT_EQ(taken_back_count(), back + 1);
  release.set_value();
  const Program& first = cached_compute_program(fill_program, "#define SCALE 7.0\n");  // the worker's
  EXPECT_EQ(taken_back_count(), back + 1);
  EXPECT_EQ(linked_ahead_count(), ahead + 2);
  EXPECT_EQ(warmed_count(), warmed + 2);
  EXPECT_EQ(fill(first)[3], 63.0f);  // 7·3²
  EXPECT_EQ(fill(second)[3], 72.0f);
  std::thread::id ran_first, ran_second;
  run_where_warmed(first, [&] { ran_first = std::this_thread::get_id(); });
  run_where_warmed(second, [&] { ran_second = std::this_thread::get_id(); });
  EXPECT_NE(ran_first, std::this_thread::get_id());
  EXPECT_EQ(ran_second, std::this_thread::get_id());
  context.check("taken back");
}

// Holds the worker in a warm-up until release(): what is queued after waits.
class HeldWorker {
public:
  HeldWorker() {
    link_compute_ahead("gpu/test_shaders/fill.comp.glsl", "#define SCALE 9.0\n", [this](const Program&) {
      started_.set_value();
      released_.wait();
    });
    started_.get_future().wait();
  }
  void release() { release_.set_value(); }
  ~HeldWorker() { cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 9.0\n"); }

private:
  std::promise<void> started_, release_;
  std::shared_future<void> released_ = release_.get_future().share();
};

// Programs linked together are taken back together: asked for one, the
// others are compiled and warmed here too when asked, none by the worker.
TEST(Gpu, ProgramsLinkedTogetherAreTakenBackTogether) {
  Context& context = Context::headless();
  const char* fill_program = "gpu/test_shaders/fill.comp.glsl";
  HeldWorker held;
  std::vector<std::thread::id> warmed_on;
  link_compute_ahead_together({{fill_program, "#define SCALE 10.0\n"}, {fill_program, "#define SCALE 11.0\n"}},
                              [&](const Program&) { warmed_on.push_back(std::this_thread::get_id()); });
  const int back = taken_back_count();
  const Program& first = cached_compute_program(fill_program, "#define SCALE 10.0\n");
  held.release();
  stop_linking();  // whatever the worker still had, it has done
  const Program& second = cached_compute_program(fill_program, "#define SCALE 11.0\n");
  EXPECT_EQ(taken_back_count(), back + 2);
  EXPECT_EQ(warmed_on, std::vector<std::thread::id>(2, std::this_thread::get_id()));
  EXPECT_EQ(programs_linking(), 1) << "the held program is asked for when `held` goes";
  EXPECT_EQ(fill(first)[2], 40.0f);  // 10·2²
  EXPECT_EQ(fill(second)[2], 44.0f);
  context.check("linked together");
}

// Work for the worker's context goes before the links it has not begun: the
// frame waits for it, and they are ahead of their use.
TEST(Gpu, WorkInTheWorkerContextGoesBeforeLinksNotBegun) {
  Context& context = Context::headless();
  HeldWorker held;
  bool linked = false;
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", "#define SCALE 12.0\n", [&](const Program&) { linked = true; });
  std::thread releaser([&] {  // once the work is queued behind the held job, beside the link
    while (worker_jobs_waiting() < 2) std::this_thread::yield();
    held.release();
  });
  bool linked_before = true;
  run_in_worker_context([&] { linked_before = linked; });
  releaser.join();
  EXPECT_FALSE(linked_before);
  cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 12.0\n");
  EXPECT_TRUE(linked);
  context.check("work before links");
}

// Work in the worker's context sees what this context wrote before it, and
// this context sees what the work wrote; without an error in between.
TEST(Gpu, WorkInTheWorkerContextIsOrderedWithThisContexts) {
  Context& context = Context::headless();
  const Program& program = cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 2.0\n");
  constexpr int count = 100;
  const Buffer mine = make_buffer(count * sizeof(float), nullptr), theirs = make_buffer(count * sizeof(float), nullptr);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, mine.id());
  glUseProgram(program.id());
  set_uniform(program, "count", count);
  glDispatchCompute(2, 1, 1);
  std::vector<float> seen(count);
  std::thread::id ran_on;
  run_in_worker_context([&] {
    ran_on = std::this_thread::get_id();
    glGetNamedBufferSubData(mine.id(), 0, count * sizeof(float), seen.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, theirs.id());
    glUseProgram(program.id());
    set_uniform(program, "count", count / 2);
    glDispatchCompute(2, 1, 1);
  });
  EXPECT_NE(ran_on, std::this_thread::get_id());
  EXPECT_EQ(seen[9], 162.0f);  // 2·9²
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<float> written(count);
  glGetNamedBufferSubData(theirs.id(), 0, count * sizeof(float), written.data());
  EXPECT_EQ(written[49], 4802.0f);  // 2·49², within the worker's count of 50
  context.check("worker context");
}

// What the work throws, and a GL error it raises, are thrown here; the
// worker goes on with the next.
TEST(Gpu, WorkerContextErrorsAreThrownHere) {
  Context::headless();
  EXPECT_EQ(failure_text([] { run_in_worker_context([] { throw Failure("from the worker"); }); }),
            "from the worker");
  EXPECT_EQ(failure_text([] { run_in_worker_context([] { glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1u << 20, 0); }); }),
            "GL error 0x0501 in a pass in the worker's context");
  bool ran = false;
  run_in_worker_context([&] { ran = true; });
  EXPECT_TRUE(ran);
}

// stop_linking ends the worker after what it was asked to link (the viewer
// calls it before its worker's window goes); the next link_ahead starts another.
TEST(Gpu, StoppedWorkerFinishesItsLinksAndTheNextLinkStartsAnother) {
  Context& context = Context::headless();
  const int ahead = linked_ahead_count();
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", "#define SCALE 5.0\n");
  stop_linking();
  const Program& first = cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 5.0\n");
  const int back = taken_back_count();
  link_compute_ahead("gpu/test_shaders/fill.comp.glsl", "#define SCALE 6.0\n");
  stop_linking();
  const Program& second = cached_compute_program("gpu/test_shaders/fill.comp.glsl", "#define SCALE 6.0\n");
  EXPECT_EQ(linked_ahead_count(), ahead + 2);
  EXPECT_EQ(taken_back_count(), back) << "the second worker did not link it";
  EXPECT_EQ(fill(first)[3], 45.0f);
  EXPECT_EQ(fill(second)[3], 54.0f);
  context.check("stop linking");
}

TEST(Gpu, GlErrorsBecomeFailures) {
  Context& context = Context::headless();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 987654);  // not a buffer name: GL_INVALID_OPERATION/VALUE
  const std::string text = failure_text([&] { context.check("a deliberate misuse"); });
  EXPECT_NE(text.find("OpenGL error in a deliberate misuse"), std::string::npos) << text;
  EXPECT_NO_THROW(context.check("nothing"));  // the errors were consumed
}

}  // namespace
}  // namespace airlight::gpu
