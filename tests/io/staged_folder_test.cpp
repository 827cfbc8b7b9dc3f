#include "animkit/io/staged_folder.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <vector>

#include "../support/temp_files.h"
#include "animkit/io/atomic_write.h"

namespace animkit {
namespace {

namespace fs = std::filesystem;
using testing_support::fresh_dir;
using testing_support::read_file;

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(StagedFolder, ANewFolderAppearsOnlyWhenCommitted) {
  const fs::path parent = fresh_dir("staged_new");
  auto folder = StagedFolder::begin(parent / "a" / "run");
  ASSERT_TRUE(folder) << folder.error().message;
  ASSERT_TRUE(write_file_atomic(folder->dir() / "metrics.json", "{}"));
  EXPECT_FALSE(fs::exists(parent / "a" / "run"));
  ASSERT_TRUE(folder->commit());
  EXPECT_EQ(entries(parent / "a" / "run"),
            (std::vector<std::string>{".animkit-outputs", "metrics.json"}));
  EXPECT_EQ(entries(parent / "a"), (std::vector<std::string>{"run"}));  // no staging left
  EXPECT_NE(read_file(parent / "a" / "run" / ".animkit-outputs").find("\nmetrics.json\n"),
            std::string::npos);
}

TEST(StagedFolder, TheNewSetReplacesTheOldWholeNeverAMix) {
  const fs::path parent = fresh_dir("staged_replace");
  for (const std::vector<std::string>& set :
       {std::vector<std::string>{"metrics.json", "path.csv", "drawing.svg"},
        std::vector<std::string>{"metrics.json", "cloth.pc2"}}) {
    auto folder = StagedFolder::begin(parent / "out");
    ASSERT_TRUE(folder) << folder.error().message;
    for (const std::string& name : set) {
      ASSERT_TRUE(write_file_atomic(folder->dir() / name, "new " + name));
    }
    ASSERT_TRUE(folder->commit());
  }
  EXPECT_EQ(entries(parent / "out"),
            (std::vector<std::string>{".animkit-outputs", "cloth.pc2", "metrics.json"}));
  EXPECT_EQ(entries(parent), (std::vector<std::string>{"out"}));
}

TEST(StagedFolder, AnAbandonedRunLeavesThePreviousSetAndNoStaging) {
  const fs::path parent = fresh_dir("staged_abandon");
  {
    auto folder = StagedFolder::begin(parent / "out");
    ASSERT_TRUE(folder);
    ASSERT_TRUE(write_file_atomic(folder->dir() / "metrics.json", "circle"));
    ASSERT_TRUE(folder->commit());
  }
  {
    auto folder = StagedFolder::begin(parent / "out");
    ASSERT_TRUE(folder);
    ASSERT_TRUE(write_file_atomic(folder->dir() / "metrics.json", "star"));
  }  // fails before commit
  EXPECT_EQ(read_file(parent / "out" / "metrics.json"), "circle");
  EXPECT_EQ(entries(parent), (std::vector<std::string>{"out"}));
}

TEST(StagedFolder, RefusesFoldersThatHoldTheUsersOwnFiles) {
  const fs::path parent = fresh_dir("staged_foreign");
  fs::create_directories(parent / "home");
  std::ofstream(parent / "home" / "thesis.tex") << "years of work";
  std::ofstream(parent / "home" / "metrics.json") << "{}";
  const auto folder = StagedFolder::begin(parent / "home");
  ASSERT_FALSE(folder);
  EXPECT_EQ(folder.error().message,
            "output folder " + (parent / "home").string() +
                " holds 'thesis.tex', which animkit did not write; a run replaces its folder "
                "whole, so give it a new or empty folder");
  std::ofstream(parent / "file") << "x";
  EXPECT_EQ(StagedFolder::begin(parent / "file").error().message,
            "output folder " + (parent / "file").string() + " is a file, not a folder");
}

TEST(StagedFolder, RefusesTheCurrentFolderAndItsAncestors) {
  const fs::path parent = fresh_dir("staged_cwd");
  fs::create_directories(parent / "inside");
  const fs::path saved = fs::current_path();
  fs::current_path(parent / "inside");
  const auto here = StagedFolder::begin(".");
  const auto above = StagedFolder::begin("..");
  fs::current_path(saved);
  ASSERT_FALSE(here);
  ASSERT_FALSE(above);
  EXPECT_NE(here.error().message.find("is the current folder or contains it"), std::string::npos);
}

TEST(StagedFolder, FilesNamedInTheTargetGoIntoTheStagingFolder) {
  const fs::path parent = fresh_dir("staged_redirect");
  auto folder = StagedFolder::begin(parent / "out");
  ASSERT_TRUE(folder);
  EXPECT_EQ(*folder->redirect(parent / "out" / "v.mp4"), folder->dir() / "v.mp4");
  EXPECT_EQ(*folder->redirect(parent / "v.mp4"), parent / "v.mp4");
  EXPECT_FALSE(folder->redirect(parent / "out" / "sub" / "v.mp4"));
}

}  // namespace
}  // namespace animkit
