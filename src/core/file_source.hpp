#pragma once
// Where the loaders read their input files: the disk for the command, a map in
// memory for the fuzz targets and tests (docs/design.md §4), so a loader takes
// the bytes and the files they name without touching the disk itself.
#include <filesystem>
#include <map>
#include <string>

namespace airlight {

class FileSource {
public:
  virtual ~FileSource() = default;
  // Whether `file` is there to read (a regular file on disk).
  virtual bool exists(const std::filesystem::path& file) const = 0;
  // The bytes of `file`; throws InputError(file, "", "cannot read the file") when it cannot.
  virtual std::string read(const std::filesystem::path& file) const = 0;
};

// The files on disk.
const FileSource& disk_files();

// Files held in memory, by their path as given.
class MemoryFiles : public FileSource {
public:
  void add(const std::filesystem::path& file, std::string bytes) { files_[file] = std::move(bytes); }
  bool exists(const std::filesystem::path& file) const override { return files_.contains(file); }
  std::string read(const std::filesystem::path& file) const override;

private:
  std::map<std::filesystem::path, std::string> files_;
};

}  // namespace airlight
