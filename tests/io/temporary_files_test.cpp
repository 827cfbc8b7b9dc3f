#include "animkit/io/temporary_files.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "../support/temp_files.h"

namespace animkit {
namespace {

namespace fs = std::filesystem;
using testing_support::fresh_dir;
using testing_support::read_file;

// The pid of a process that has ended and been reaped: no process has it now.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  return child;
}

fs::path with_pid(const fs::path& path, pid_t pid, const std::string& kind) {
  fs::path named = path;
  named += ".animkit-" + std::to_string(pid) + "-0123456789ab." + kind;
  return named;
}

TEST(TemporaryFiles, NamesAreUniqueAndRecognised) {
  const fs::path a = unique_sibling("/x/cloth.pc2", "tmp");
  const fs::path b = unique_sibling("/x/cloth.pc2", "tmp");
  EXPECT_NE(a, b);
  EXPECT_EQ(a.parent_path(), "/x");
  pid_t pid = 0;
  ASSERT_TRUE(is_animkit_temporary(a.filename().string(), pid));
  EXPECT_EQ(pid, ::getpid());
  EXPECT_FALSE(is_animkit_temporary("cloth.pc2", pid));
  EXPECT_FALSE(is_animkit_temporary("cloth.pc2.tmp", pid));
  EXPECT_FALSE(is_animkit_temporary("a.animkit-12-0123456789ab.exe", pid));
  EXPECT_FALSE(is_animkit_temporary("a.animkit-x-0123456789ab.tmp", pid));
}

TEST(TemporaryFiles, StaleOnesOfDeadRunsAreRemovedLiveOnesKept) {
  const fs::path dir = fresh_dir("stale_temporaries");
  const pid_t dead = dead_pid();
  std::ofstream(with_pid(dir / "cloth.pc2", dead, "tmp")) << "17 MB of a killed run";
  std::ofstream(with_pid(dir / "v.mp4", dead, "log")) << "log";
  fs::create_directories(with_pid(dir / "out", dead, "staging") / "ik");
  const fs::path mine = with_pid(dir / "path.csv", ::getpid(), "tmp");
  std::ofstream(mine) << "being written";
  std::ofstream(dir / "notes.tmp") << "not ours";
  remove_stale_temporaries(dir);
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(dir)) left.push_back(entry.path().filename());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"notes.tmp", mine.filename().string()}));
}

TEST(TemporaryFiles, AnOldFolderWhoseSwapDiedIsPutBack) {
  const fs::path dir = fresh_dir("stale_old_folder");
  const fs::path old = with_pid(dir / "results", dead_pid(), "old");
  fs::create_directories(old);
  std::ofstream(old / "metrics.json") << "{}";
  remove_stale_temporaries(dir);
  EXPECT_FALSE(fs::exists(old));
  EXPECT_EQ(read_file(dir / "results" / "metrics.json"), "{}");
}

}  // namespace
}  // namespace animkit
