#include "core/atomic_file.hpp"

#include <airlight/error.hpp>

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <stdexcept>

namespace airlight {

namespace fs = std::filesystem;

namespace {

thread_local OutputBatch* open_batch = nullptr;

fs::path temp_beside(const fs::path& target) {
  static std::atomic<int> counter{0};
  return fs::path(target).replace_extension(".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++) +
                                            target.extension().string());
}

void remove_temporaries(std::vector<OutputBatch::Pending>& files) {
  std::error_code ec;
  for (auto& f : files) fs::remove(f.temp, ec);
  files.clear();
}

// Renames every temporary over its target with the stop signals held, so that a
// signal lands before the first rename or after the last.
void rename_all(std::vector<OutputBatch::Pending>& files) {
  const SignalsHeld held;
  for (auto& f : files) {
    std::error_code ec;
    fs::rename(f.temp, f.target, ec);
    if (ec) {
      const std::string message = "cannot write " + f.target.string() + ": " + ec.message();
      remove_temporaries(files);
      throw Failure(message);
    }
    pause_point("renamed:" + f.target.filename().string());
  }
  files.clear();
}

}  // namespace

void write_atomically(const fs::path& target, const std::function<void(const fs::path& temp)>& write) {
  const fs::path temp = temp_beside(target);
  Unfinished unfinished(temp.string(), Unfinished::Kind::file);  // before the file exists
  std::error_code ec;
  try {
    write(temp);
  } catch (const Failure& e) {
    fs::remove(temp, ec);
    // The writer's message names the temporary file; the user knows the target.
    std::string what = e.what();
    for (size_t at; (at = what.find(temp.string())) != std::string::npos;)
      what.replace(at, temp.string().size(), target.string());
    throw Failure(what);
  } catch (...) {
    fs::remove(temp, ec);
    throw;
  }
  pause_point("written:" + target.filename().string());
  std::vector<OutputBatch::Pending> file;
  file.push_back({target, temp, std::move(unfinished)});
  if (open_batch) return open_batch->add(std::move(file.front()));
  rename_all(file);
}

void write_text_file(const fs::path& file, const std::string& text) {
  write_atomically(file, [&](const fs::path& temp) {
    std::ofstream out(temp);
    if (!(out << text) || !out.flush()) throw Failure("cannot write " + file.string());
  });
}

OutputBatch::OutputBatch() {
  if (open_batch) throw std::logic_error("an OutputBatch is open on this thread already");
  open_batch = this;
}

OutputBatch::~OutputBatch() {
  if (open_batch == this) open_batch = nullptr;
  remove_temporaries(files_);
  std::error_code ec;
  for (auto it = directories_.rbegin(); it != directories_.rend(); ++it) fs::remove(it->first, ec);
}

void OutputBatch::create_directories(const fs::path& dir) {
  std::vector<fs::path> missing;
  std::error_code ec;
  for (fs::path level = dir; !level.empty() && !fs::exists(level, ec); level = level.parent_path()) {
    missing.push_back(level);
    if (level == level.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    Unfinished unfinished(it->string(), Unfinished::Kind::directory);  // before it exists
    if (!fs::create_directory(*it, ec) && ec) throw Failure("cannot create " + dir.string() + ": " + ec.message());
    directories_.emplace_back(*it, std::move(unfinished));
  }
}

void OutputBatch::add(Pending file) { files_.push_back(std::move(file)); }

void OutputBatch::commit() {
  rename_all(files_);
  directories_.clear();
  if (open_batch == this) open_batch = nullptr;
}

}  // namespace airlight
