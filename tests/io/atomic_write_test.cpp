#include "animkit/io/atomic_write.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
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

TEST(AtomicWrite, AFailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path dir = fresh_dir("atomic_write_fail");
  ASSERT_TRUE(write_file_atomic(dir / "keep.txt", "old"));
  {
    auto file = AtomicFile::create(dir / "keep.txt");
    ASSERT_TRUE(file);
    std::fputs("half of the new", file->stream());
    const auto result = file->commit(/*ok=*/false);
    ASSERT_FALSE(result);
    EXPECT_EQ(result.error().message.rfind("cannot write " + (dir / "keep.txt").string(), 0), 0u);
  }
  EXPECT_EQ(read_file(dir / "keep.txt"), "old");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

TEST(AtomicWrite, FailureNamesThePath) {
  const fs::path dir = fresh_dir("atomic_write_no_folder");
  const auto result = write_file_atomic(dir / "missing" / "a.txt", "x");
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message,
            "cannot write " + (dir / "missing" / "a.txt").string() + ": No such file or directory");
}

TEST(AtomicWrite, NeverWritesThroughALinkPlantedAtATemporaryName) {
  // The temporary used to be "<name>.tmp": a link planted there made the write overwrite the
  // file it pointed to.
  const fs::path dir = fresh_dir("atomic_write_symlink");
  ASSERT_TRUE(write_file_atomic(dir / "victim.txt", "precious"));
  fs::create_symlink(dir / "victim.txt", dir / "path.csv.tmp");
  ASSERT_TRUE(write_file_atomic(dir / "path.csv", "frame,x\n"));
  EXPECT_EQ(read_file(dir / "victim.txt"), "precious");
  EXPECT_EQ(read_file(dir / "path.csv"), "frame,x\n");
}

TEST(AtomicWrite, TwoWritersOfOneFileUseTwoTemporariesAndTheLastWinsWhole) {
  const fs::path dir = fresh_dir("atomic_write_two");
  auto first = AtomicFile::create(dir / "cloth.pc2");
  auto second = AtomicFile::create(dir / "cloth.pc2");
  ASSERT_TRUE(first && second);
  std::fputs("first writer's whole file", first->stream());
  std::fputs("second", second->stream());
  ASSERT_TRUE(first->commit());
  EXPECT_EQ(read_file(dir / "cloth.pc2"), "first writer's whole file");
  ASSERT_TRUE(second->commit());
  EXPECT_EQ(read_file(dir / "cloth.pc2"), "second");
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
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
