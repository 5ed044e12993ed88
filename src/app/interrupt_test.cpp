// Interrupted runs and a shared reference cache (issue 26; README "Interrupted
// runs", "The reference cache"): the command is stopped at a named point by
// $AIRLIGHT_TEST_PAUSE_AT (core/interrupt.hpp), sent a real SIGINT or SIGTERM,
// and must die by it leaving no temporary file, no partial output and no half
// cache entry.
#include "app/command_test_support.hpp"
#include "core/image_io.hpp"
#include "core/warning.hpp"
#include "reference/cache.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <regex>
#include <set>
#include <thread>

extern char** environ;

namespace airlight {
namespace {

using namespace test;

// A fresh, empty directory of this test's own.
fs::path fresh_dir(const std::string& name) {
  const fs::path dir = work_dir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// Every file and directory under `dir`, relative to it.
std::set<std::string> contents(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(fs::relative(e.path(), dir).string());
  return names;
}

// `airlight ARGS` started with $AIRLIGHT_TEST_PAUSE_AT=pause (none when empty),
// SIGINT and SIGTERM at their default actions, its output in `dir`.
pid_t start(const std::string& args, const std::string& pause, const fs::path& dir) {
  std::vector<std::string> strings{airlight_exe().string()};
  std::istringstream words(args);
  for (std::string w; words >> w;) strings.push_back(w);
  std::vector<std::string> env_strings;
  for (char** e = environ; *e; ++e) env_strings.emplace_back(*e);
  if (!pause.empty()) env_strings.push_back("AIRLIGHT_TEST_PAUSE_AT=" + pause);
  auto pointers = [](std::vector<std::string>& v) {
    std::vector<char*> p;
    for (auto& s : v) p.push_back(s.data());
    p.push_back(nullptr);
    return p;
  };
  std::vector<char*> argv = pointers(strings), envp = pointers(env_strings);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t set;
  sigemptyset(&set);
  posix_spawnattr_setsigmask(&attr, &set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  posix_spawnattr_setsigdefault(&attr, &set);  // a shell's background job inherits SIGINT ignored
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, (dir / "stdout.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&files, 2, (dir / "stderr.txt").c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, argv[0], &files, &attr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&files);
  posix_spawnattr_destroy(&attr);
  EXPECT_EQ(error, 0) << std::strerror(error);
  return pid;
}

// waitpid's status once the process stops (WUNTRACED) or ends.
int wait_for(pid_t pid) {
  int status = 0;
  EXPECT_EQ(::waitpid(pid, &status, WUNTRACED), pid);
  return status;
}

std::string describe(int status, const fs::path& dir) {
  return "status " + std::to_string(status) + ", stderr: " + read_text(dir / "stderr.txt");
}

// A thread of `pid` other than its main one that does not block `sig`: a TBB
// worker (Mesa's threads block every signal). -1 when there is none.
pid_t unblocking_thread(pid_t pid, int sig) {
  for (const auto& task : fs::directory_iterator("/proc/" + std::to_string(pid) + "/task")) {
    const pid_t tid = std::stoi(task.path().filename().string());
    std::istringstream status(read_text(task.path() / "status"));
    for (std::string line; std::getline(status, line);)
      if (line.rfind("SigBlk:", 0) == 0 && tid != pid && !(std::stoull(line.substr(7), nullptr, 16) >> (sig - 1) & 1))
        return tid;
  }
  return -1;
}

// Runs `airlight ARGS` to the pause point, sends `sig` there (to the process,
// or to one of its worker threads), and expects it killed by that signal.
void interrupt(const std::string& args, const std::string& pause, int sig, const fs::path& dir,
               bool to_worker = false) {
  const pid_t pid = start(args, pause, dir);
  const int stopped = wait_for(pid);
  ASSERT_TRUE(WIFSTOPPED(stopped)) << "never reached " << pause << ": " << describe(stopped, dir);
  if (to_worker) {
    const pid_t worker = unblocking_thread(pid, sig);
    if (worker < 0) {
      ::kill(pid, SIGKILL);  // not left stopped
      wait_for(pid);
      FAIL() << "no thread besides the main one takes the signal";
    }
    ::syscall(SYS_tgkill, pid, worker, sig);
  } else {
    ::kill(pid, sig);
  }
  ::kill(pid, SIGCONT);
  const int ended = wait_for(pid);
  EXPECT_TRUE(WIFSIGNALED(ended) && WTERMSIG(ended) == sig) << describe(ended, dir);
}

// A small scene whose reference renders in 0.1 s (0.3 s under ASan); the
// shared cache's test reads its entry back.
const std::string scene = " --builtin biri_media --size 16x12";
const std::string bench = "bench --methods raymarch --frames 1 --warmup 0 --builtin biri_media --sizes 16x12";

// Output files only: the work folder less the run's stdout and stderr.
std::set<std::string> outputs(const fs::path& dir) {
  std::set<std::string> names = contents(dir);
  names.erase("stdout.txt");
  names.erase("stderr.txt");
  return names;
}

// The names are the folder "cache" and one entry in it.
void expect_only_a_cache_entry_in(const std::set<std::string>& left) {
  ASSERT_EQ(left.size(), 2u);
  EXPECT_EQ(*left.begin(), "cache");
  EXPECT_TRUE(std::regex_match(*left.rbegin(), std::regex("cache/[0-9a-f]{16}\\.ref"))) << *left.rbegin();
}

TEST(Interrupt, RenderBetweenATemporaryFilesWriteAndItsRenameLeavesNothing) {
  const fs::path dir = fresh_dir("render_temp");
  interrupt("render --method raymarch" + scene + " --out " + (dir / "out.png").string(), "written:out.png", SIGINT,
            dir);
  EXPECT_EQ(outputs(dir), std::set<std::string>{});
}

// The image is complete under its temporary name when the report's is written:
// the old image stays as it was, and neither new file appears.
TEST(Interrupt, RenderBetweenItsTwoOutputsLeavesTheOldOnes) {
  const fs::path dir = fresh_dir("render_two"), image = dir / "out.pfm";
  std::ofstream(image) << "old";
  interrupt("render --method raymarch" + scene + " --out " + image.string() + " --report " +
                (dir / "out.json").string(),
            "written:out.json", SIGTERM, dir);
  EXPECT_EQ(outputs(dir), std::set<std::string>{"out.pfm"});
  EXPECT_EQ(read_text(image), "old");
}

// The reference's cache entry is committed (whole) before the outputs are
// written; the images' directory, made by this run, goes with them.
TEST(Interrupt, CompareBetweenItsOutputsLeavesNoneAndAWholeCacheEntry) {
  const fs::path dir = fresh_dir("compare_two");
  interrupt("compare --methods raymarch" + scene + " --cache " + (dir / "cache").string() + " --images " +
                (dir / "images/new").string() + " --csv " + (dir / "errors.csv").string() + " --out " +
                (dir / "sheet.png").string(),
            "written:errors.csv", SIGTERM, dir);
  expect_only_a_cache_entry_in(outputs(dir));
}

TEST(Interrupt, CompareMidCacheEntryLeavesNoEntry) {
  const fs::path dir = fresh_dir("compare_cache");
  interrupt("compare --methods raymarch" + scene + " --cache " + (dir / "cache").string() + " --out " +
                (dir / "sheet.png").string(),
            "written:*.ref", SIGINT, dir);
  EXPECT_EQ(outputs(dir), std::set<std::string>{"cache"});  // the cache's folder, empty
}

// A signal that reaches a worker thread (the reference renders on TBB's) is
// forwarded to the main thread, which holds it while it commits the outputs:
// all of them are renamed into place before the signal ends the run.
TEST(Interrupt, ASignalToAWorkerThreadDuringTheCommitWaitsForItsEnd) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one core: TBB starts no worker thread";
  const fs::path dir = fresh_dir("worker");
  interrupt("compare --methods raymarch" + scene + " --cache " + (dir / "cache").string() + " --csv " +
                (dir / "errors.csv").string() + " --out " + (dir / "sheet.png").string(),
            "renamed:errors.csv", SIGTERM, dir, true);
  std::set<std::string> left = outputs(dir);
  ASSERT_EQ(left.erase("errors.csv") + left.erase("sheet.png"), 2u);
  expect_only_a_cache_entry_in(left);
  EXPECT_EQ(read_csv(dir / "errors.csv").size(), 3u);  // the header, the reference and raymarch
  EXPECT_EQ(read_image(dir / "sheet.png").empty(), false);
}

TEST(Interrupt, BenchBetweenItsOutputsLeavesNone) {
  const fs::path dir = fresh_dir("bench_two");
  interrupt(bench + " --cache " + (dir / "cache").string() +
                " --csv " + (dir / "times.csv").string() + " --plot " + (dir / "plot.png").string(),
            "written:times.csv", SIGINT, dir);
  expect_only_a_cache_entry_in(outputs(dir));
}

// Two processes fill one empty cache with the same reference: the first stops
// with its entry written under a temporary name, the second renders, stores and
// finishes meanwhile, then the first goes on and renames its entry over the
// second's. Both succeed, neither warns, and one whole entry is left, which
// reads back from the cache.
TEST(SharedCache, TwoProcessesFillingOneEmptyCacheBothSucceed) {
  const fs::path dir = fresh_dir("shared"), cache = dir / "cache";
  const auto args = [&](const std::string& name) {
    return "compare --methods raymarch" + scene + " --cache " + cache.string() + " --csv " +
           (dir / (name + ".csv")).string() + " --out " + (dir / (name + ".png")).string();
  };
  const fs::path first_dir = fresh_dir("shared_first");
  const pid_t first = start(args("first"), "written:*.ref", first_dir);
  ASSERT_TRUE(WIFSTOPPED(wait_for(first)));
  const Outcome second = run_airlight(args("second"));
  EXPECT_EQ(second.status, 0) << second.err;
  EXPECT_NE(second.err.find("compare: reference rendered into the cache"), std::string::npos) << second.err;
  ::kill(first, SIGCONT);
  const int ended = wait_for(first);
  EXPECT_TRUE(WIFEXITED(ended) && WEXITSTATUS(ended) == 0) << describe(ended, first_dir);
  for (const std::string& err : {read_text(first_dir / "stderr.txt"), second.err})
    EXPECT_EQ(err.find("warning"), std::string::npos) << err;
  const std::set<std::string> entries = contents(cache);
  ASSERT_EQ(entries.size(), 1u);
  EXPECT_TRUE(std::regex_match(*entries.begin(), std::regex("[0-9a-f]{16}\\.ref"))) << *entries.begin();
  const Table a = read_csv(dir / "first.csv"), b = read_csv(dir / "second.csv");
  const size_t mean = column(a, "reference_mean");
  EXPECT_EQ(a.at(1).at(mean), b.at(1).at(mean));
  CapturedWarnings warnings;
  EXPECT_TRUE(reference::cached_reference(builtin_scene("biri_media"), 16, 12, cache).cached);
  EXPECT_EQ(warnings.text(), "");
}

}  // namespace
}  // namespace airlight
