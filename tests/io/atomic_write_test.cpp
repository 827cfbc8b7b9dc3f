#include "animkit/io/atomic_write.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/temp_files.h"

namespace animkit {
namespace {

namespace fs = std::filesystem;

using testing_support::fresh_dir;
using testing_support::read_file;

TEST(AtomicWrite, ReplacesTheFileWholeAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("atomic_write_replace");
  ASSERT_TRUE(write_file_atomic(dir / "a.txt", "first"));
  ASSERT_TRUE(write_file_atomic(dir / "a.txt", "second version"));
  EXPECT_EQ(read_file(dir / "a.txt"), "second version");
  EXPECT_FALSE(fs::exists(dir / "a.txt.tmp"));
}

TEST(AtomicWrite, FailureNamesThePathAndKeepsTheOldFile) {
  const fs::path dir = fresh_dir("atomic_write_fail");
  ASSERT_TRUE(write_file_atomic(dir / "keep.txt", "old"));
  // A directory where the temporary file should go makes the write fail.
  fs::create_directories(dir / "keep.txt.tmp");
  const auto result = write_file_atomic(dir / "keep.txt", "new");
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message.rfind("cannot write " + (dir / "keep.txt").string(), 0), 0u);
  EXPECT_EQ(read_file(dir / "keep.txt"), "old");
}

TEST(OutputDirectory, IsCreatedWithItsParents) {
  const fs::path dir = fresh_dir("output_dir") / "a" / "b";
  ASSERT_TRUE(ensure_output_directory(dir));
  EXPECT_TRUE(fs::is_directory(dir));
}

TEST(OutputDirectory, AFileInTheWayIsAnError) {
  const fs::path dir = fresh_dir("output_dir_file");
  ASSERT_TRUE(write_file_atomic(dir / "file", "x"));
  const auto result = ensure_output_directory(dir / "file" / "sub");
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message.rfind("cannot create output folder", 0), 0u);
}

}  // namespace
}  // namespace animkit
