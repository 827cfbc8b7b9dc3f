// Reading input files whole (io/file_bytes.h): what is read and what is refused up front.
#include "animkit/io/file_bytes.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <fstream>
#include <string>

#include "animkit/core/quote.h"
#include "../support/temp_files.h"

namespace animkit {
namespace {

TEST(FileBytes, ReadsAFileWholeAndRefusesWhatIsNotOne) {
  const std::filesystem::path dir = testing_support::fresh_dir("file_bytes");
  std::ofstream(dir / "small.txt") << "hello";
  EXPECT_EQ(*read_file_bytes(dir / "small.txt", 100), "hello");
  EXPECT_EQ(read_file_bytes(dir / "small.txt", 4).error().message,
            (dir / "small.txt").string() + ": 5 bytes, larger than the limit of 4 bytes");
  EXPECT_EQ(read_file_bytes(dir / "none.txt", 100).error().message,
            (dir / "none.txt").string() + ": no such file");
  EXPECT_EQ(read_file_bytes(dir, 100).error().message, dir.string() + ": is a folder, not a file");
  // A device never ends: refused at once, not read up to the limit.
  EXPECT_EQ(read_file_bytes("/dev/zero", std::uintmax_t{1} << 30).error().message,
            "/dev/zero: is a device, not a file");
  // The system would open "small.txt" and the message would stop at the NUL.
  const std::string with_nul = (dir / "small.txt").string() + std::string(1, '\0') + ".json";
  EXPECT_EQ(read_file_bytes(with_nul, 100).error().message,
            (dir / "small.txt").string() + "\\x00.json: a path cannot hold a NUL byte");
}

// A path from a scene file can be any length: the message keeps its start and the file's name.
TEST(FileBytes, ALongPathIsShownByItsEnds) {
  const std::string path = "/nonexistent/" + std::string(2000, 'x') + "/none.obj";
  const std::string message = read_file_bytes(path, 100).error().message;
  EXPECT_TRUE(message.starts_with("/nonexistent/")) << message;
  EXPECT_TRUE(message.ends_with("/none.obj: no such file")) << message;
  EXPECT_LE(message.size(), kShownPathChars + std::string(": no such file").size());
}

TEST(FileBytes, ReadsAPipeUpToTheLimit) {
  const std::filesystem::path fifo = testing_support::fresh_dir("file_bytes_fifo") / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A writer in the background, like `--scene <(generate)`.
  ASSERT_EQ(std::system(("sh -c 'printf abc > " + fifo.string() + "' &").c_str()), 0);
  EXPECT_EQ(*read_file_bytes(fifo, 100), "abc");
}

}  // namespace
}  // namespace animkit
