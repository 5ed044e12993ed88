#include "core/atomic_file.hpp"

#include <airlight/error.hpp>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <unistd.h>

namespace airlight {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir() {
  const fs::path dir = fs::temp_directory_path() / ("airlight_atomic_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string text_of(const fs::path& file) {
  std::stringstream text;
  text << std::ifstream(file).rdbuf();
  return text.str();
}

size_t entries(const fs::path& dir) { return std::distance(fs::directory_iterator(dir), fs::directory_iterator()); }

// A writer that fails leaves the old file as it was and nothing beside it; its
// message names the target, not the temporary name it wrote to.
TEST(AtomicFile, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const fs::path dir = fresh_dir(), target = dir / "out.csv";
  write_text_file(target, "old\n");
  try {
    write_atomically(target, [](const fs::path& temp) {
      EXPECT_EQ(temp.extension(), ".csv");  // writers pick the format by the extension
      std::ofstream(temp) << "half";
      throw Failure("cannot write " + temp.string() + ": disk full");
    });
    ADD_FAILURE() << "no error";
  } catch (const Failure& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + target.string() + ": disk full");
  }
  EXPECT_EQ(text_of(target), "old\n");
  EXPECT_EQ(entries(dir), 1u);
  write_text_file(target, "new\n");
  EXPECT_EQ(text_of(target), "new\n");
  EXPECT_EQ(entries(dir), 1u);
  fs::remove_all(dir);
}

// A batch's files stay under their temporary names until its commit; dropped
// uncommitted (an error on the way), it leaves the old files and removes the
// directories it made.
TEST(AtomicFile, ABatchChangesTheFilesAtItsCommitOrNotAtAll) {
  const fs::path dir = fresh_dir(), old = dir / "a.csv", made = dir / "new" / "deeper", added = made / "b.csv";
  write_text_file(old, "old\n");
  for (const bool commit : {false, true}) {
    {
      OutputBatch batch;
      batch.create_directories(made);
      write_text_file(old, "new\n");
      write_text_file(added, "b\n");
      EXPECT_EQ(text_of(old), "old\n");
      EXPECT_FALSE(fs::exists(added));
      if (commit) batch.commit();
    }
    EXPECT_EQ(text_of(old), commit ? "new\n" : "old\n");
    EXPECT_EQ(entries(dir), commit ? 2u : 1u) << "commit " << commit;  // a.csv, and new/ once committed
  }
  EXPECT_EQ(text_of(added), "b\n");
  EXPECT_EQ(entries(made), 1u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace airlight
