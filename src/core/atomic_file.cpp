#include "core/atomic_file.hpp"

#include <airlight/error.hpp>

#include <unistd.h>

#include <atomic>
#include <fstream>

namespace airlight {

namespace fs = std::filesystem;

namespace {

fs::path temp_beside(const fs::path& target) {
  static std::atomic<int> counter{0};
  return fs::path(target).replace_extension(".tmp" + std::to_string(::getpid()) + "_" + std::to_string(counter++) +
                                            target.extension().string());
}

}  // namespace

void write_atomically(const fs::path& target, const std::function<void(const fs::path& temp)>& write) {
  const fs::path temp = temp_beside(target);
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
  fs::rename(temp, target, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw Failure("cannot write " + target.string() + ": " + ec.message());
  }
}

void write_text_file(const fs::path& file, const std::string& text) {
  write_atomically(file, [&](const fs::path& temp) {
    std::ofstream out(temp);
    if (!(out << text) || !out.flush()) throw Failure("cannot write " + file.string());
  });
}

}  // namespace airlight
