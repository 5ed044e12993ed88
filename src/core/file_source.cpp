#include "core/file_source.hpp"

#include <airlight/error.hpp>

#include <fstream>
#include <sstream>

namespace airlight {
namespace {

[[noreturn]] void unreadable(const std::filesystem::path& file) {
  throw InputError(file.string(), "", "cannot read the file");
}

class DiskFiles : public FileSource {
public:
  bool exists(const std::filesystem::path& file) const override { return std::filesystem::is_regular_file(file); }

  std::string read(const std::filesystem::path& file) const override {
    std::ifstream in(file, std::ios::binary);
    if (!in || std::filesystem::is_directory(file)) unreadable(file);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
  }
};

}  // namespace

const FileSource& disk_files() {
  static const DiskFiles files;
  return files;
}

std::string MemoryFiles::read(const std::filesystem::path& file) const {
  const auto it = files_.find(file);
  if (it == files_.end()) unreadable(file);
  return it->second;
}

}  // namespace airlight
