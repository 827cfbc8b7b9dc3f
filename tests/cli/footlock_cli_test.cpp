// Behaviour tests of `animkit footlock` on the CMU walk (skipped without the data): the files
// it writes and its one-line errors.
#pragma GCC diagnostic ignored "-Wuninitialized"  // GCC 12 AVX-512 false positive (dense Eigen)
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "../support/run_command.h"
#include "../support/temp_files.h"
#include "animkit/io/bvh.h"
#include "animkit/io/foot_lock_report.h"
#include "animkit/io/png.h"
#include "animkit/io/video_writer.h"

namespace footlock_cli_test {

namespace fs = std::filesystem;
using animkit::testing_support::read_file;
using animkit::testing_support::run_command;

const std::string kCli = ANIMKIT_CLI_PATH;
const fs::path kWalk = ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh";

fs::path fresh_dir(const std::string& name) {
  return animkit::testing_support::fresh_dir("cli_footlock_" + name);
}

TEST(FootlockCli, LocksTheWalkAndWritesClipMetricsAndPicture) {
  ASSERT_TRUE(fs::exists(kWalk)) << kWalk << " is not here";
  const fs::path out = fresh_dir("walk") / "run";
  const auto r = run_command(kCli + " footlock --in " + kWalk.string() + " --out " + out.string() +
                             " --scale 0.056444");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("contacts left 8 right 8"), std::string::npos) << r.out;

  const auto metrics = nlohmann::json::parse(read_file(out / "metrics.json"));
  EXPECT_EQ(metrics["frames"], 994);
  EXPECT_EQ(metrics["contacts"]["left"], 8);
  EXPECT_EQ(metrics["contacts"]["right"], 8);
  EXPECT_EQ(metrics["scale"]["metres_per_unit"], 0.056444);
  EXPECT_EQ(metrics["scale"]["description"], "scale 0.056444 m per file unit (given)");
  const double before = metrics["sliding_cm_per_frame"]["before"]["mean"];
  const double after = metrics["sliding_cm_per_frame"]["after"]["mean"];
  EXPECT_LT(after, 0.5);
  EXPECT_LT(after, before);
  EXPECT_LT(metrics["sliding_cm_per_frame"]["after"]["max"].get<double>(), 0.5);
  for (const char* key : {"ik_error_cm", "max_joint_step_cm", "max_leg_step_cm", "ms_per_frame",
                          "settings", "planted_frames"}) {
    EXPECT_TRUE(metrics.contains(key)) << key;
  }

  // fixed.bvh is in the file's own units: same skeleton, same frames, the legs changed.
  const auto original = animkit::read_bvh_file(kWalk);
  const auto fixed = animkit::read_bvh_file(out / "fixed.bvh");
  ASSERT_TRUE(original);
  ASSERT_TRUE(fixed) << fixed.error().message;
  EXPECT_EQ(fixed->frame_count(), original->frame_count());
  ASSERT_EQ(fixed->joint_count(), original->joint_count());
  for (int j = 0; j < fixed->joint_count(); ++j) {
    EXPECT_TRUE(
        fixed->skeleton.rest_offsets[j].isApprox(original->skeleton.rest_offsets[j], 1e-9) ||
        original->skeleton.rest_offsets[j].norm() < 1e-12)
        << j;
  }
  EXPECT_NEAR(fixed->motion(0, 1), original->motion(0, 1), 1e-9);  // root height, file units
  EXPECT_GT((fixed->motion - original->motion).cwiseAbs().maxCoeff(), 1e-3);

  const auto picture = animkit::read_image(out / "compare.png");
  ASSERT_TRUE(picture) << picture.error().message;
  EXPECT_EQ(picture->width, animkit::kFootLockPlotWidth);
  EXPECT_EQ(picture->height, 2 * animkit::kFootLockPlotHeight);
}

TEST(FootlockCli, VideoShowsTheWalkAtSixtyFramesPerSecond) {
  ASSERT_TRUE(fs::exists(kWalk)) << kWalk << " is not here";
  if (!animkit::find_ffmpeg()) GTEST_SKIP() << "ffmpeg is not installed";
  const fs::path out = fresh_dir("video") / "run";
  // Small frames: 497 of them at the default 960 x 720 take 20 s to render and encode.
  const auto r = run_command(kCli + " footlock --in " + kWalk.string() +
                             " --scale 0.056444 --out " + out.string() + " --video " +
                             (out / "walk.mp4").string() + " --video-size 160x120");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(out / "fixed.bvh"));
  // 994 frames at 120 fps, every second one kept.
  const auto probe = run_command(
      "ffprobe -v error -count_frames -select_streams v:0 "
      "-show_entries stream=width,height,nb_read_frames -of csv=p=0 " +
      (out / "walk.mp4").string());
  EXPECT_EQ(probe.out, "160,120,497\n");
}

TEST(FootlockCli, InIsRequired) {
  const auto r = run_command(kCli + " footlock --out " + (fresh_dir("no_in") / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "animkit: error: --in is required (see animkit footlock --help)\n");
}

TEST(FootlockCli, BadSettingsAndFilesAreOneLineErrorsAndWriteNothing) {
  const fs::path dir = fresh_dir("errors");
  const std::string out = " --out " + (dir / "o").string();
  auto r = run_command(kCli + " footlock --in " + kWalk.string() + out + " --blend -1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "animkit: error: foot lock blend must be >= 0 frames, got -1\n");
  r = run_command(kCli + " footlock --in " + kWalk.string() + out + " --knee-pole back");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "animkit: error: unknown --knee-pole 'back' (expected pelvis-forward or original)\n");
  r = run_command(kCli + " footlock --in " + kWalk.string() + out + " --scale 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "animkit: error: --scale must be a number > 0 (metres per file unit), got 0\n");
  r = run_command(kCli + " footlock --in " + (dir / "missing.bvh").string() + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("missing.bvh"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o"));
}

TEST(FootlockCli, AClipInCentimetresIsLockedWithoutScaleAndSaysTheScale) {
  if (!fs::exists(kWalk)) GTEST_SKIP() << kWalk << " is not here";
  // The walk written in centimetres: CMU's units x 5.6444.
  const fs::path dir = fresh_dir("centimetres");
  const auto clip = animkit::read_bvh_file(kWalk, {.scale = 5.6444});
  ASSERT_TRUE(clip && animkit::write_bvh_file(dir / "walk_cm.bvh", *clip));
  const auto r = run_command(kCli + " footlock --in " + (dir / "walk_cm.bvh").string() + " --out " +
                             (dir / "o").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("footlock: scale 0.01 m per file unit (detected: centimetres, legs 80.2 "
                        "units long)\n",
                        0),
            0u)
      << r.out;
  EXPECT_NE(r.out.find("contacts left 8 right 8"), std::string::npos) << r.out;
  // metrics.json keeps the scale and how it was found.
  const auto metrics = nlohmann::json::parse(read_file(dir / "o" / "metrics.json"));
  EXPECT_EQ(metrics["scale"]["metres_per_unit"], 0.01);
  EXPECT_EQ(metrics["scale"]["description"],
            "scale 0.01 m per file unit (detected: centimetres, legs 80.2 units long)");
}

TEST(FootlockCli, AWrongScaleFindsNoContactAndFailsInOneLine) {
  if (!fs::exists(kWalk)) GTEST_SKIP() << kWalk << " is not here";
  const fs::path dir = fresh_dir("wrong_scale");
  const auto r = run_command(kCli + " footlock --in " + kWalk.string() + " --scale 1 --out " +
                             (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "animkit: error: " + kWalk.string() +
                       ": no foot contact in 994 frames: no ankle stays within 0.05 m of the "
                       "lowest ankle height at under 0.35 m/s; the legs are 14.2 m long (a "
                       "person's are about 0.8 m): is the clip in metres? (scale 1 m per file "
                       "unit (given); --scale sets it)\n");
  EXPECT_FALSE(fs::exists(dir / "o"));
}

}  // namespace footlock_cli_test
