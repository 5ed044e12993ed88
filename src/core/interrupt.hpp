#pragma once
// Interrupted runs (issue 26, docs/design.md §5 "Interrupted runs"): SIGINT or
// SIGTERM removes the files this run has not finished — temporary files and the
// directories it created for outputs not yet committed — and then kills the
// process by the same signal, so its parent sees it killed by the signal.
#include <memory>
#include <string>

namespace airlight {

// Installs the handler for SIGINT and SIGTERM; a signal the process inherited
// as ignored (nohup, a shell's background job) stays ignored. Call once, from
// the main thread, before any other thread starts: the handler does its work on
// that thread, and any other thread that receives a signal forwards it there.
void remove_unfinished_files_on_interrupt();

// A file or directory removed if a signal arrives while it lives; from then on,
// nothing removes it. Registering throws Failure only when 1024 are
// registered at once; the handler never allocates, it only unlinks (rmdir for
// a directory) what is registered.
class Unfinished {
public:
  enum class Kind { file, directory };
  Unfinished(const std::string& path, Kind kind);
  ~Unfinished();
  Unfinished(Unfinished&&) noexcept;
  Unfinished& operator=(Unfinished&&) = delete;
  Unfinished(const Unfinished&) = delete;
  Unfinished& operator=(const Unfinished&) = delete;

private:
  int slot_ = -1;  // -1: moved from
};

// SIGINT and SIGTERM held (blocked) in this thread while it lives: a signal
// that arrives meanwhile is handled when it ends, so what runs in its scope is
// never cut in half (a commit's renames).
class SignalsHeld {
public:
  SignalsHeld();
  ~SignalsHeld();
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;
};

// A test hook: when $AIRLIGHT_TEST_PAUSE_AT matches `point` (a glob, fnmatch(3)),
// the process stops itself (SIGSTOP, which a parent's waitpid sees with
// WUNTRACED) and, once continued, waits there 1 s for a signal the test sent
// meanwhile before it goes on. Points (core/atomic_file.hpp): "written:<file
// name>", a file written under its temporary name and not yet renamed;
// "renamed:<file name>", a file renamed into place, the commit's later renames
// still to come (the stop signals held).
void pause_point(const std::string& point);

}  // namespace airlight
