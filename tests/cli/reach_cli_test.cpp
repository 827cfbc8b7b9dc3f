// Behaviour tests of `animkit reach` on the CMU walk: a hand reaches a target while the feet
// stay planted; the files it writes, what it says of unreachable targets, its one-line errors.
#pragma GCC diagnostic ignored "-Wuninitialized"  // GCC 12 AVX-512 false positive (dense Eigen)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "../support/run_command.h"
#include "../support/temp_files.h"
#include "animkit/io/bvh.h"
#include "animkit/io/png.h"
#include "animkit/io/reach_report.h"

namespace reach_cli_test {

namespace fs = std::filesystem;
using animkit::Vec3;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;
const fs::path kWalk = ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh";
constexpr double kScale = 0.056444;  // CMU's file units to metres
constexpr int kFrame = 300;

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("cli_reach_" + name);
}

// Frame `frame` of `clip` (read in metres) with FK run.
animkit::SkeletonPose frame_pose(const animkit::BvhClip& clip, const animkit::Skeleton& skeleton,
                                 int frame) {
  animkit::SkeletonPose pose = animkit::skeleton_rest_pose(skeleton);
  animkit::bvh_frame_to_pose(clip, frame, pose);
  animkit::skeleton_forward_kinematics(skeleton, pose);
  return pose;
}

std::string target_args(const Vec3& t) {
  std::ostringstream s;
  s.precision(17);
  s << " --target " << t.x() << ' ' << t.y() << ' ' << t.z();
  return s.str();
}

// The walk's frame, a target in front of the chest and to the left, reached by every solver:
// the hand lands on it, the feet and the root stay, and reached.bvh holds that pose.
TEST(ReachCli, EverySolverReachesWithTheFeetPlanted) {
  ASSERT_TRUE(fs::exists(kWalk)) << kWalk << " is not here";
  const auto clip = animkit::read_bvh_file(kWalk, {.scale = kScale});
  ASSERT_TRUE(clip) << clip.error().message;
  const auto skeleton = animkit::build_skeleton(clip->skeleton);
  ASSERT_TRUE(skeleton);
  const animkit::SkeletonPose before = frame_pose(*clip, *skeleton, kFrame);
  const int hand = skeleton->find_joint("lhand"), chest = skeleton->find_joint("Chest2");
  const int feet[] = {skeleton->find_joint("LeftAnkle"), skeleton->find_joint("RightAnkle")};
  const int root = skeleton->roots().front();
  // 35 cm from the hand, half a metre from the chest: within reach, not where the hand was.
  const Vec3 target = before.global_positions[chest] + Vec3(0.25, 0.15, 0.0) +
                      0.25 * (before.global_positions[chest] - before.global_positions[root])
                                 .cross(Vec3::UnitY())
                                 .normalized();
  ASSERT_GT((target - before.global_positions[hand]).norm(), 0.2);

  for (const char* solver : {"dls", "sdls", "fabrik", "ccd"}) {
    const fs::path out = fresh_dir(solver) / "run";
    const auto r =
        run_command(kCli + " reach --in " + kWalk.string() + " --scale 0.056444" + " --frame " +
                    std::to_string(kFrame) + " --hand left" + target_args(target) + " --solver " +
                    solver + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << solver << ": " << r.err;
    EXPECT_EQ(r.out.find("unreachable"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("not reached"), std::string::npos) << r.out;

    const auto metrics = nlohmann::json::parse(read_file(out / "metrics.json"));
    EXPECT_EQ(metrics["solver"], solver);
    EXPECT_EQ(metrics["hand"], "lhand");
    EXPECT_EQ(metrics["frame"], kFrame);
    EXPECT_EQ(metrics["reachable"], true);
    EXPECT_EQ(metrics["reached"], true) << solver;
    EXPECT_EQ(metrics["converged"], true) << solver;
    EXPECT_LT(metrics["hand_error_cm"].get<double>(), 0.01) << solver;  // 1e-4 m
    EXPECT_LT(metrics["foot_drift_cm"].get<double>(), 0.01) << solver;
    EXPECT_EQ(metrics["root_drift_cm"].get<double>(), 0.0) << solver;
    EXPECT_GE(metrics["iterations"].get<int>(), 1);
    EXPECT_TRUE(metrics.contains("solve_ms"));
    EXPECT_NE(metrics["limits"].get<std::string>().find("default human limits"), std::string::npos);

    // reached.bvh: the one reached frame, in file units; read back, the hand is on the target,
    // the feet and root where the walk had them.
    const auto reached = animkit::read_bvh_file(out / "reached.bvh", {.scale = kScale});
    ASSERT_TRUE(reached) << reached.error().message;
    ASSERT_EQ(reached->frame_count(), 1);
    const animkit::SkeletonPose after = frame_pose(*reached, *skeleton, 0);
    EXPECT_LT((after.global_positions[hand] - target).norm(), 2e-4) << solver;
    for (int foot : feet) {
      EXPECT_LT((after.global_positions[foot] - before.global_positions[foot]).norm(), 2e-4)
          << solver;
    }
    EXPECT_LT((after.global_positions[root] - before.global_positions[root]).norm(), 1e-9);
    EXPECT_LT(after.local_rotations[root].angularDistance(before.local_rotations[root]), 1e-6);
    // The right arm plays no part: it keeps its pose relative to the chest.
    const int right_hand = skeleton->find_joint("rhand");
    const Vec3 right_before =
        before.global_rotations[chest].conjugate() *
        (before.global_positions[right_hand] - before.global_positions[chest]);
    const Vec3 right_after = after.global_rotations[chest].conjugate() *
                             (after.global_positions[right_hand] - after.global_positions[chest]);
    EXPECT_LT((right_after - right_before).norm(), 1e-4) << solver;

    const auto picture = animkit::read_image(out / "reach.png");
    ASSERT_TRUE(picture) << picture.error().message;
    EXPECT_EQ(picture->width, 2 * animkit::kReachViewWidth);
    EXPECT_EQ(picture->height, animkit::kReachPictureHeight);
  }
}

TEST(ReachCli, UnreachableTargetWritesTheClosestPoseAndSaysSo) {
  const fs::path out = fresh_dir("far") / "run";
  const auto r = run_command(kCli + " reach --in " + kWalk.string() +
                             " --scale 0.056444 --hand right --target 5 1 0 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("unreachable"), std::string::npos) << r.out;
  const auto metrics = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(metrics["hand"], "rhand");
  EXPECT_EQ(metrics["reachable"], false);
  EXPECT_EQ(metrics["reached"], false);
  EXPECT_GT(metrics["hand_error_cm"].get<double>(), 100.0);
  EXPECT_LT(metrics["foot_drift_cm"].get<double>(), 0.01);
  EXPECT_TRUE(fs::exists(out / "reached.bvh"));
  EXPECT_TRUE(fs::exists(out / "reach.png"));
}

TEST(ReachCli, BadInputIsOneLineAndWritesNothing) {
  const fs::path dir = fresh_dir("errors");
  std::ofstream(dir / "typo.json") << R"({"LeftElbowe": {"type": "free"}})";
  // A one-joint clip with no frames, and the same with two: not a biped.
  const std::string stick =
      "HIERARCHY\nROOT hip\n{\n\tOFFSET 0 0 0\n\tCHANNELS 3 Xposition "
      "Yposition Zposition\n\tEnd Site\n\t{\n\t\tOFFSET 0 1 0\n\t}\n}\n"
      "MOTION\nFrame Time: 0.1\n";
  std::ofstream(dir / "empty.bvh")
      << stick.substr(0, stick.find("Frame Time")) + "Frames: 0\nFrame Time: 0.1\n";
  std::ofstream(dir / "stick.bvh")
      << stick.substr(0, stick.find("Frame Time")) + "Frames: 2\nFrame Time: 0.1\n0 0 0\n0 0 0\n";
  const std::string in = " --in " + kWalk.string() + " --scale 0.056444";
  const std::pair<std::string, std::string> cases[] = {
      {"reach" + in + " --target nan 1 0",
       "--target must be three finite numbers X Y Z (metres), got (nan, 1, 0)"},
      {"reach" + in + " --target 0 inf 0", "--target must be three finite numbers"},
      {"reach" + in + " --target 1 2", "--target"},
      {"reach" + in + " --target 0 1 0 --hand middle",
       "--hand must be left or right, got 'middle'"},
      {"reach" + in + " --target 0 1 0 --frame 994", "--frame must be in [0, 993]"},
      {"reach" + in + " --target 0 1 0 --frame -1", "--frame must be in [0, 993]"},
      {"reach" + in + " --target 0 1 0 --solver jacobian",
       "unknown solver 'jacobian' (expected fabrik, ccd, dls or sdls)"},
      {"reach" + in + " --target 0 1 0 --limits " + (dir / "typo.json").string(), "LeftElbowe"},
      {"reach" + in + " --target 0 1 0 --limits " + (dir / "missing.json").string(),
       "missing.json"},
      {"reach" + in + " --target 0 1 0 --tolerance 0", "tolerance must be a positive"},
      {"reach --in " + (dir / "missing.bvh").string() + " --target 0 1 0", "missing.bvh"},
      {"reach" + in, "--target is required"},
      {"reach --in " + (dir / "empty.bvh").string() + " --target 0 1 0 --scale 1",
       "empty.bvh: the clip has no frames"},
      {"reach --in " + (dir / "stick.bvh").string() + " --target 0 1 0 --scale 1",
       "stick.bvh: no joint named LeftHip: a biped's legs are found by name"},
      {"reach --in " + (dir / "stick.bvh").string() + " --target 0 1 0",
       "stick.bvh: cannot tell its units: no joint named LeftHip: a biped's legs are found by "
       "name (LeftHip, LeftKnee, LeftAnkle and the same on the right); give the file's scale "
       "(metres per unit) with --scale"},
  };
  for (const auto& [args, message] : cases) {
    const auto r = run_command(kCli + " " + args + " --out " + (dir / "o").string());
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "o")) << args;
  }
}

TEST(ReachCli, HelpExplainsEveryOption) {
  const auto r = run_command(kCli + " reach --help");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* option : {"--in", "--frame", "--hand", "--target", "--scale", "--limits",
                             "--solver", "--max-iterations", "--tolerance", "--out"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
  const auto ik = run_command(kCli + " ik --help");
  EXPECT_NE(ik.out.find("--limits"), std::string::npos);
  EXPECT_NE(run_command(kCli + " --help").out.find("reach"), std::string::npos);
}

TEST(ReachCli, TheTargetTakesCommasAsIkDoesAndSpacesToo) {
  if (!fs::exists(kWalk)) GTEST_SKIP() << kWalk << " is not here";
  const fs::path dir = fresh_dir("target_forms");
  const auto commas = run_command(kCli + " reach --in " + kWalk.string() +
                                  " --target 0.6,1.4,-1.35 --out " + (dir / "a").string());
  const auto spaces = run_command(kCli + " reach --in " + kWalk.string() +
                                  " --target 0.6 1.4 -1.35 --out " + (dir / "b").string());
  ASSERT_EQ(commas.exit_code, 0) << commas.err;
  ASSERT_EQ(spaces.exit_code, 0) << spaces.err;
  EXPECT_EQ(read_file(dir / "a" / "reached.bvh"), read_file(dir / "b" / "reached.bvh"));
}

}  // namespace reach_cli_test
