#include "core/interrupt.hpp"

#include <airlight/error.hpp>

#include <fnmatch.h>
#include <pthread.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>

namespace airlight {

namespace {

struct Entry {
  Unfinished::Kind kind;
  std::string path;  // immutable while registered: the handler reads its c_str()
};

// Each slot holds a registered entry, nullptr when free, or `taken` once the
// handler has claimed it. Registration publishes a complete entry by one
// atomic store and the handler claims one by one exchange, so neither sees the
// other's half-done work, whichever thread runs either (std::atomic of a
// pointer is lock-free, thus safe in a handler).
constexpr int capacity = 1024;
std::array<std::atomic<Entry*>, capacity> slots{};
Entry taken_marker{Unfinished::Kind::file, {}};
Entry* const taken = &taken_marker;

pthread_t main_thread;
constexpr std::array<int, 2> stop_signals{SIGINT, SIGTERM};

bool removed(const Entry& e) {
  return (e.kind == Unfinished::Kind::file ? ::unlink(e.path.c_str()) : ::rmdir(e.path.c_str())) == 0;
}

// Async-signal-safe: atomics, unlink, rmdir, signal, pthread_sigmask, raise.
void on_stop_signal(int sig) {
  if (!pthread_equal(pthread_self(), main_thread)) {
    // Run where the registering code runs, so it is interrupted, not racing.
    pthread_kill(main_thread, sig);
    return;
  }
  std::array<Entry*, capacity> claimed;
  int n = 0;
  for (auto& slot : slots)
    if (Entry* e = slot.exchange(taken); e && e != taken) claimed[n++] = e;
  for (int i = 0; i < n; ++i)
    if (claimed[i]->kind == Unfinished::Kind::file) removed(*claimed[i]);
  // Directories deepest first: an rmdir succeeds once the levels below are gone.
  for (bool progress = true; progress;) {
    progress = false;
    for (int i = 0; i < n; ++i)
      if (claimed[i] && claimed[i]->kind == Unfinished::Kind::directory && removed(*claimed[i])) {
        claimed[i] = nullptr;
        progress = true;
      }
  }
  std::signal(sig, SIG_DFL);
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, sig);
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  std::raise(sig);
}

sigset_t stop_set() {
  sigset_t set;
  sigemptyset(&set);
  for (int sig : stop_signals) sigaddset(&set, sig);
  return set;
}

}  // namespace

void remove_unfinished_files_on_interrupt() {
  main_thread = pthread_self();
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  action.sa_mask = stop_set();  // one handler at a time: the first signal decides
  for (int sig : stop_signals) {
    struct sigaction previous {};
    sigaction(sig, nullptr, &previous);
    if (previous.sa_handler != SIG_IGN) sigaction(sig, &action, nullptr);
  }
}

Unfinished::Unfinished(const std::string& path, Kind kind) {
  auto* entry = new Entry{kind, path};
  for (int i = 0; i < capacity; ++i) {
    Entry* expected = nullptr;
    if (slots[i].compare_exchange_strong(expected, entry)) {
      slot_ = i;
      return;
    }
  }
  delete entry;
  throw Failure("cannot write " + path + ": more than " + std::to_string(capacity) + " files unfinished at once");
}

Unfinished::~Unfinished() {
  if (slot_ < 0) return;
  Entry* entry = slots[slot_].load();
  // Fails only when the handler has claimed the entry: it may be reading it,
  // and the process is about to end, so it stays.
  if (entry != taken && slots[slot_].compare_exchange_strong(entry, nullptr)) delete entry;
}

Unfinished::Unfinished(Unfinished&& other) noexcept : slot_(other.slot_) { other.slot_ = -1; }

SignalsHeld::SignalsHeld() {
  const sigset_t set = stop_set();
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
}

SignalsHeld::~SignalsHeld() {
  const sigset_t set = stop_set();
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
}

void pause_point(const std::string& point) {
  const char* wanted = std::getenv("AIRLIGHT_TEST_PAUSE_AT");
  if (!wanted || ::fnmatch(wanted, point.c_str(), 0) != 0) return;
  std::raise(SIGSTOP);
  // A signal sent while stopped may wake another thread, which forwards it
  // here: wait for it, so the process is interrupted at this point, not later.
  std::this_thread::sleep_for(std::chrono::seconds(1));
}

}  // namespace airlight
