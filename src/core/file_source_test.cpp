#include "core/file_source.hpp"

#include <airlight/error.hpp>
#include <gtest/gtest.h>

#include <fstream>

namespace airlight {
namespace {

std::string read_error(const FileSource& files, const std::filesystem::path& file) {
  try {
    files.read(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "read";
}

TEST(FileSource, DiskReadsBytesAndNamesWhatItCannotRead) {
  const auto dir = std::filesystem::temp_directory_path() / "airlight_file_source";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "a.bin", std::ios::binary) << std::string("x\0y", 3);
  EXPECT_TRUE(disk_files().exists(dir / "a.bin"));
  EXPECT_EQ(disk_files().read(dir / "a.bin"), std::string("x\0y", 3));
  EXPECT_FALSE(disk_files().exists(dir));  // a folder is no file
  EXPECT_EQ(read_error(disk_files(), dir), dir.string() + ": cannot read the file");
  EXPECT_EQ(read_error(disk_files(), dir / "missing"), (dir / "missing").string() + ": cannot read the file");
}

TEST(FileSource, MemoryHoldsTheFilesAddedByPath) {
  MemoryFiles files;
  files.add("/m/a.obj", "v 0 0 0\n");
  EXPECT_TRUE(files.exists("/m/a.obj"));
  EXPECT_FALSE(files.exists("/m/b.obj"));
  EXPECT_EQ(files.read("/m/a.obj"), "v 0 0 0\n");
  EXPECT_EQ(read_error(files, "/m/b.obj"), "/m/b.obj: cannot read the file");
}

}  // namespace
}  // namespace airlight
