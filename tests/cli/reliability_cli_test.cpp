// Nothing lost, nothing half-written: full disks, concurrent runs, runs that fail part-way,
// signals and stale temporaries. A full disk is simulated with RLIMIT_FSIZE (`ulimit
// -f`, SIGXFSZ ignored): every write past the limit fails with EFBIG as it would with ENOSPC,
// in the CLI and in the ffmpeg it starts.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "../support/run_command.h"
#include "../support/temp_files.h"

extern char** environ;

namespace reliability_cli_test {

namespace fs = std::filesystem;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("reliability_" + name);
}

// Every entry of `dir`, sorted, "name/" for folders.
std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) {
    names.push_back(e.path().filename().string() + (e.is_directory() ? "/" : ""));
  }
  std::sort(names.begin(), names.end());
  return names;
}

// Runs `command` with writes limited to `kib` KiB, as on a nearly full disk.
animkit::testing_support::CommandOutput run_on_full_disk(const std::string& command, int kib) {
  return run_command("sh -c 'trap \"\" XFSZ; ulimit -f " + std::to_string(kib) + "; " + command +
                     "'");
}

// The points count in a PC2 header.
std::int32_t pc2_points(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  char header[32] = {};
  in.read(header, sizeof header);
  std::int32_t points = 0;
  std::memcpy(&points, header + 16, sizeof points);
  return points;
}

TEST(FullDisk, AVideoCutShortIsAnErrorAndLeavesNothing) {
  // Small frames: the videos (about 28 KB and 54 KB) still pass the limit, and ffmpeg, which
  // reads every frame before it reports the failed write, takes a second instead of seven.
  for (const char* name : {"v.mp4", "v.gif"}) {
    const fs::path dir = fresh_dir(std::string("video_") + name);
    const auto r = run_on_full_disk(
        kCli + " ik --shape circle --picture-size 160x120 --video " + (dir / name).string(),
        /*kib=*/8);
    EXPECT_EQ(r.exit_code, 2) << r.out << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << r.err;
    EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
    EXPECT_TRUE(fs::is_empty(dir)) << entries(dir).size();  // no video, no temporary, no log
  }
}

TEST(FullDisk, ARunThatFailsPartWayLeavesThePreviousCompleteSet) {
  const fs::path dir = fresh_dir("ik_partial");
  const fs::path out = dir / "out";
  ASSERT_EQ(run_command(kCli + " ik --shape circle --no-picture --out " + out.string()).exit_code,
            0);
  const auto before = entries(out);
  const std::string path_csv = read_file(out / "path.csv");
  // The star's path.csv is larger than the limit: the run fails while writing its files.
  const auto r =
      run_on_full_disk(kCli + " ik --shape star --no-picture --out " + out.string(), /*kib=*/16);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(entries(out), before);
  EXPECT_EQ(read_file(out / "path.csv"), path_csv);
  EXPECT_EQ(nlohmann::json::parse(read_file(out / "metrics.json"))["shape"], "circle");
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out/"});  // no staging folder left
}

TEST(FullDisk, AClothRunThatFailsKeepsItsFolderConsistent) {
  const fs::path dir = fresh_dir("cloth_partial");
  const fs::path out = dir / "out";
  ASSERT_EQ(run_command(kCli + " cloth --frames 10 --no-picture --out " + out.string()).exit_code,
            0);
  const auto r = run_on_full_disk(
      kCli + " cloth --frames 201 --grid 40 --no-picture --out " + out.string(), /*kib=*/64);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  const auto metrics = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(metrics["frames"], 10);
  EXPECT_EQ(pc2_points(out / "cloth.pc2"), 121);
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out/"});
}

TEST(ConcurrentRuns, TwoRunsIntoOneFolderLeaveOneWholeSet) {
  const fs::path dir = fresh_dir("concurrent");
  const fs::path out = dir / "out";
  for (int round = 0; round < 3; ++round) {
    const auto r = run_command(
        kCli + " cloth --grid 20 --frames 40 --no-picture --out " + out.string() + " & " + kCli +
        " cloth --grid 40 --frames 30 --no-picture --out " + out.string() + " & wait");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto metrics = nlohmann::json::parse(read_file(out / "metrics.json"));
    const int particles = metrics["particles"];
    EXPECT_TRUE(particles == 441 || particles == 1681) << particles;
    EXPECT_EQ(pc2_points(out / "cloth.pc2"), particles);
    const std::string obj = read_file(out / "cloth.obj");
    int vertices = 0;
    for (std::size_t at = obj.find("\nv "); at != std::string::npos;
         at = obj.find("\nv ", at + 1)) {
      ++vertices;
    }
    EXPECT_EQ(vertices, particles);
    EXPECT_EQ(entries(dir), std::vector<std::string>{"out/"});
  }
}

TEST(ConcurrentRuns, ALinkPlantedAtAnOldTemporaryNameIsNeverWrittenThrough) {
  const fs::path dir = fresh_dir("symlink");
  std::ofstream(dir / "victim") << "precious";
  fs::create_directories(dir / "out");
  fs::create_symlink(dir / "victim", dir / "out" / "path.csv.tmp");
  const auto r =
      run_command(kCli + " ik --shape circle --no-picture --out " + (dir / "out").string());
  // The folder holds something animkit did not write: refused, and nothing written anywhere.
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(read_file(dir / "victim"), "precious");
}

// Starts the CLI directly (no shell: a shell would start it with SIGINT ignored).
pid_t start_cli(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {kCli};
  argv.insert(argv.end(), args.begin(), args.end());
  std::vector<char*> raw;
  for (std::string& a : argv) raw.push_back(a.data());
  raw.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  EXPECT_EQ(posix_spawn(&pid, kCli.c_str(), &actions, nullptr, raw.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// Waits until `dir` holds an entry whose name contains `part` (at most 60 s).
bool wait_for_entry(const fs::path& dir, const std::string& part) {
  for (int i = 0; i < 6000; ++i) {
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().filename().string().find(part) != std::string::npos) return true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

TEST(Signals, SigintAndSigtermRemoveEveryTemporaryAndKeepThePreviousSet) {
  for (int signal_number : {SIGINT, SIGTERM}) {
    const fs::path dir = fresh_dir("signal_" + std::to_string(signal_number));
    const fs::path out = dir / "out";
    ASSERT_EQ(run_command(kCli + " cloth --frames 5 --no-picture --out " + out.string()).exit_code,
              0);
    const auto before = entries(out);
    // Long enough to be stopped mid-run, with a video (ffmpeg running) and a cache streaming.
    const pid_t pid =
        start_cli({"cloth", "--grid", "60", "--frames", "100000", "--out", out.string(),
                   "--no-picture", "--video", (dir / "v.mp4").string()});
    ASSERT_TRUE(wait_for_entry(dir, ".staging"));
    ASSERT_TRUE(wait_for_entry(dir, "v.mp4.animkit-"));
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    ::kill(pid, signal_number);
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal_number) << status;
    EXPECT_EQ(entries(dir), std::vector<std::string>{"out/"});  // no video, log or staging
    EXPECT_EQ(entries(out), before);
  }
}

TEST(Signals, WhatAKilledRunLeftIsRemovedByTheNextRun) {
  const fs::path dir = fresh_dir("sigkill");
  const fs::path out = dir / "out";
  const pid_t pid = start_cli(
      {"cloth", "--grid", "60", "--frames", "100000", "--out", out.string(), "--no-picture"});
  ASSERT_TRUE(wait_for_entry(dir, ".staging"));
  ::kill(pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  EXPECT_EQ(entries(dir).size(), 1u);  // the staging folder a killed run cannot remove
  const auto r = run_command(kCli + " cloth --frames 5 --no-picture --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(entries(dir), std::vector<std::string>{"out/"});
}

TEST(StandardOutput, AFullStandardOutputIsAnError) {
  const auto r = run_command("sh -c '" + kCli + " ik --target 1,0,0 >/dev/full'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "animkit: error: cannot write the results to standard output: No space left on "
            "device\n");
}

TEST(VideoPaths, ATooLongOrUnwritableVideoPathIsOneLine) {
  const fs::path dir = fresh_dir("video_paths");
  const std::string long_name = (dir / (std::string(300, 'v') + ".mp4")).string();
  for (const std::string& video : {long_name, std::string("/proc/v.mp4")}) {
    const auto r = run_command(kCli + " ik --shape circle --video " + video);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("animkit: error: cannot write ", 0), 0u) << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

TEST(VideoPaths, AVideoInTheOutFolderArrivesWithTheRest) {
  const fs::path out = fresh_dir("video_in_out") / "out";
  const auto r = run_command(kCli + " ik --shape circle --no-picture --out " + out.string() +
                             " --video " + (out / "v.gif").string() + " --picture-size 160x120");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(entries(out), (std::vector<std::string>{".animkit-outputs", "drawing.svg",
                                                    "metrics.json", "path.csv", "v.gif"}));
  // And a second run into it is allowed: the video is listed as the folder's own.
  const auto again = run_command(kCli + " ik --shape star --no-picture --out " + out.string());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_FALSE(fs::exists(out / "v.gif"));
}

}  // namespace reliability_cli_test
