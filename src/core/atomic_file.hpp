#pragma once
// Output files appear whole or not at all: each is written under a unique name
// beside its target and renamed over it once complete, so a failure, a signal
// (core/interrupt.hpp) or a concurrent reader never sees half a file.
#include "core/interrupt.hpp"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace airlight {

// Calls write(temp) with a fresh name in the target's directory that keeps the
// target's extension (writers pick the format by it), then renames temp over
// `target` — at once, or at the commit of the OutputBatch open on this thread.
// Removes temp when write throws or a stop signal arrives. Throws Failure when
// the rename fails.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& temp)>& write);

// `text` into `file`, atomically; Failure when it cannot be written.
void write_text_file(const std::filesystem::path& file, const std::string& text);

// A command's outputs, all at once (README "Interrupted runs"): while a batch
// is open on a thread, the files write_atomically writes there stay under their
// temporary names; commit() renames them all with the stop signals held. A run
// that fails or is interrupted before the commit leaves its output files as
// they were and no directory of its own; one that reaches it leaves every new
// output whole. One batch per thread at a time.
class OutputBatch {
public:
  OutputBatch();
  ~OutputBatch();  // uncommitted: removes the temporaries and the directories it created
  OutputBatch(const OutputBatch&) = delete;
  OutputBatch& operator=(const OutputBatch&) = delete;

  // `dir` and the levels above it that are missing; they are removed again if
  // the batch is not committed. Failure when one cannot be created.
  void create_directories(const std::filesystem::path& dir);
  void commit();

  // A file written under its temporary name (write_atomically's).
  struct Pending {
    std::filesystem::path target, temp;
    Unfinished unfinished;
  };
  void add(Pending file);

private:
  std::vector<Pending> files_;
  std::vector<std::pair<std::filesystem::path, Unfinished>> directories_;  // in the order created
};

}  // namespace airlight
