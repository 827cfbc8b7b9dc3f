// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's dense products are inlined
// with -march=native at -O1 (a false positive in the compiler's own headers, see
// psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "animkit/io/bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

#include "../support/temp_files.h"
#include "shared_constants.h"

namespace animkit {
namespace {

// The CMU walk (data/cmu in the repository; tests/CMakeLists.txt: ANIMKIT_TEST_DATA_DIR).
using testing_support::kWalk;

// Unusual on purpose: comments, tabs, CRLF, blank lines, a position channel on a non-root
// joint, rotation orders other than ZXY/ZYX, a joint without rotations, two End Sites.
constexpr const char* kOddClip =
    "# written by hand\r\nHIERARCHY\r\nROOT  pelvis\r\n{\r\n\tOFFSET 1 2 3\r\n"
    "\tCHANNELS 6 Zrotation Xposition Yrotation Yposition Xrotation Zposition\r\n"
    "\tJOINT arm\n\t{\n\t\tOFFSET 0.5 0 -0.25\n\t\tCHANNELS 4 Yrotation Xposition Zrotation "
    "Xrotation\n\n"
    "   # a comment inside\n\t\tJOINT hand\n\t\t{\n\t\t\tOFFSET 0 -1e-1 +.5\n\t\t\tCHANNELS 1 "
    "Zposition\n\t\t\tEnd Site\n\t\t\t{\n\t\t\t\tOFFSET 0 0 1\n\t\t\t}\n\t\t}\n\t}\n"
    "\tJOINT leg \n\t{\n\t\tOFFSET 0 -1 0\n\t\tCHANNELS 3 Xrotation Yrotation Zrotation\n"
    "\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 -1 0\n\t\t}\n\t}\n}\r\n"
    "MOTION\r\nFrames:\t3\r\nFrame Time: 0.04\r\n"
    "10 0.1 20 0.2 30 0.3 45 1 -90 0.125 7 1 2 3\r\n"
    "-170 -1 89.5 -2 179 -3 90 1e-3 90 1 0.25 -45 45 90\n\n"
    "0 0 0 0 0 0 0 0 0 0 0 0 0 0\r\n";

BvhClip read_ok(std::string_view text, const BvhReadOptions& options = {}) {
  auto clip = read_bvh(text, "odd.bvh", options);
  EXPECT_TRUE(clip) << clip.error().message;
  return clip ? *clip : BvhClip{};
}

std::string error_of(std::string_view text, const BvhReadOptions& options = {}) {
  const auto clip = read_bvh(text, "bad.bvh", options);
  EXPECT_FALSE(clip);
  return clip ? std::string("(no error)") : clip.error().message;
}

void expect_same_clip(const BvhClip& a, const BvhClip& b) {
  ASSERT_EQ(a.skeleton.names, b.skeleton.names);
  EXPECT_EQ(a.skeleton.parents, b.skeleton.parents);
  EXPECT_EQ(a.channels, b.channels);
  EXPECT_EQ(a.end_sites, b.end_sites);
  for (int j = 0; j < a.joint_count(); ++j) {
    EXPECT_LE((a.skeleton.rest_offsets[j] - b.skeleton.rest_offsets[j]).norm(), 1e-9);
  }
  EXPECT_NEAR(a.frame_time, b.frame_time, 1e-12);
  ASSERT_EQ(a.motion.rows(), b.motion.rows());
  ASSERT_EQ(a.motion.cols(), b.motion.cols());
  EXPECT_LE((a.motion - b.motion).cwiseAbs().maxCoeff(), 1e-9);
}

SkeletonPose pose_of(const BvhClip& clip, int frame) {
  const Skeleton skeleton = *build_skeleton(clip.skeleton);
  SkeletonPose pose = skeleton_rest_pose(skeleton);
  bvh_frame_to_pose(clip, frame, pose);
  skeleton_forward_kinematics(skeleton, pose);
  return pose;
}

TEST(Bvh, ReadsAnOddButValidClip) {
  const BvhClip clip = read_ok(kOddClip);
  EXPECT_EQ(clip.skeleton.names,
            (std::vector<std::string>{"pelvis", "arm", "hand", "hand_End", "leg", "leg_End"}));
  EXPECT_EQ(clip.skeleton.parents, (std::vector<int>{-1, 0, 1, 2, 0, 4}));
  EXPECT_EQ(clip.end_sites, (std::vector<bool>{false, false, false, true, false, true}));
  EXPECT_EQ(clip.channels[1],
            (std::vector<BvhChannel>{BvhChannel::y_rotation, BvhChannel::x_position,
                                     BvhChannel::z_rotation, BvhChannel::x_rotation}));
  EXPECT_EQ(clip.skeleton.rest_offsets[2], Vec3(0, -0.1, 0.5));
  EXPECT_EQ(clip.channel_count(), 14);
  EXPECT_EQ(clip.frame_count(), 3);
  EXPECT_DOUBLE_EQ(clip.frame_time, 0.04);
  EXPECT_DOUBLE_EQ(clip.motion(1, 7), 1e-3);
}

TEST(Bvh, ReadsAndWritesSeveralRootsAndJointsWithoutEndSites) {
  const BvhClip clip = read_ok(
      "HIERARCHY\nROOT a\n{\n OFFSET 1 2 3\n CHANNELS 4 Yrotation Xposition Zrotation Xrotation\n"
      " JOINT b\n {\n  OFFSET 0 1 0\n  CHANNELS 1 Zposition\n }\n}\nROOT c\n{\n OFFSET 0 0 0\n"
      " CHANNELS 0\n}\nMOTION\nFrames: 1\nFrame Time: 0.5\n10 1 90 -5 2\n");
  EXPECT_EQ(clip.skeleton.parents, (std::vector<int>{-1, 0, -1}));
  EXPECT_EQ(clip.end_sites, (std::vector<bool>{false, false, false}));
  EXPECT_EQ(pose_of(clip, 0).global_positions[2], Vec3::Zero());
  expect_same_clip(clip, read_ok(write_bvh(clip)));
}

TEST(Bvh, FramePoseComposesRotationsInChannelOrderAndReplacesOffsetsByPositions) {
  const BvhClip clip = read_ok(kOddClip);
  const SkeletonPose pose = pose_of(clip, 0);
  const auto about = [](int axis, double degrees) {
    return Eigen::AngleAxisd(degrees * std::numbers::pi / 180, Vec3::Unit(axis));
  };
  // Root: Zrotation 10, Yrotation 20, Xrotation 30 (file order), positions (0.1, 0.2, 0.3).
  const Quat root = Quat(about(2, 10)) * Quat(about(1, 20)) * Quat(about(0, 30));
  EXPECT_LT(pose.local_rotations[0].angularDistance(root), 1e-14);
  EXPECT_EQ(pose.global_positions[0], Vec3(0.1, 0.2, 0.3));
  // Arm: Yrotation 45, Xposition 1 (replacing 0.5), Zrotation -90, Xrotation 0.125.
  EXPECT_EQ(pose.local_translations[1], Vec3(1, 0, -0.25));
  const Quat arm = Quat(about(1, 45)) * Quat(about(2, -90)) * Quat(about(0, 0.125));
  EXPECT_LT(pose.local_rotations[1].angularDistance(arm), 1e-14);
  // Hand: only Zposition 7; its End Site hangs 1 along the hand's z.
  EXPECT_EQ(pose.local_translations[2], Vec3(0, -0.1, 7));
  const Vec3 end = pose.global_positions[0] + root * (Vec3(1, 0, -0.25) + arm * Vec3(0, -0.1, 8));
  EXPECT_LT((pose.global_positions[3] - end).norm(), 1e-13);
}

TEST(Bvh, OddClipWrittenAndReadBackIsTheSame) {
  const BvhClip clip = read_ok(kOddClip);
  const std::string text = write_bvh(clip);
  const BvhClip back = read_ok(text);
  expect_same_clip(clip, back);
  EXPECT_EQ(write_bvh(back), text);
}

TEST(Bvh, PoseToFrameAndBackGivesTheSamePositions) {
  BvhClip clip = read_ok(kOddClip);
  for (int f = 0; f < clip.frame_count(); ++f) {
    const SkeletonPose before = pose_of(clip, f);
    bvh_pose_to_frame(before, clip, f);
    const SkeletonPose after = pose_of(clip, f);
    for (int j = 0; j < clip.joint_count(); ++j) {
      EXPECT_LT((before.global_positions[j] - after.global_positions[j]).norm(), 1e-9)
          << "frame " << f << " joint " << j;
    }
  }
  // Frame 1's arm turns Zrotation 90, the middle of its order Y Z X: gimbal lock, no NaN.
  EXPECT_FALSE(clip.validate());
  EXPECT_NEAR(clip.motion(1, 8), 90.0, 1e-9);
}

TEST(Bvh, ScaleMultipliesOffsetsAndPositionsOnly) {
  const BvhClip plain = read_ok(kOddClip);
  const BvhClip scaled = read_ok(kOddClip, {.scale = 2.5});
  EXPECT_EQ(scaled.skeleton.rest_offsets[1], 2.5 * plain.skeleton.rest_offsets[1]);
  EXPECT_DOUBLE_EQ(scaled.motion(0, 1), 2.5 * plain.motion(0, 1));    // Xposition of pelvis
  EXPECT_DOUBLE_EQ(scaled.motion(0, 0), plain.motion(0, 0));          // Zrotation of pelvis
  EXPECT_DOUBLE_EQ(scaled.motion(0, 10), 2.5 * plain.motion(0, 10));  // Zposition of hand
  EXPECT_EQ(error_of(kOddClip, {.scale = 0.0}),
            "bad.bvh: the scale must be a finite number > 0, got 0");
  EXPECT_EQ(error_of(kOddClip, {.scale = std::nan("")}),
            "bad.bvh: the scale must be a finite number > 0, got nan");
}

// A minimal valid file the malformed cases below change one thing in.
std::string small_file(const std::string& joint =
                           "\tJOINT knee\n\t{\n\t\tOFFSET 0 -1 0\n"
                           "\t\tCHANNELS 3 Zrotation Xrotation Yrotation\n"
                           "\t\tEnd Site\n\t\t{\n\t\t\tOFFSET 0 -1 0\n"
                           "\t\t}\n\t}\n",
                       const std::string& motion =
                           "Frames: 2\nFrame Time: 0.1\n"
                           "0 0 0 0 0 0 1 2 3\n0 0 0 0 0 0 4 5 6\n") {
  return "HIERARCHY\nROOT hip\n{\n\tOFFSET 0 0 0\n"
         "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n" +
         joint + "}\nMOTION\n" + motion;
}

// A long joint name of bytes that are not UTF-8 is shown escaped and cut, so a message naming
// it and quoting a bad value stays one short line (a fuzz input once made it 808 bytes).
TEST(Bvh, LongBinaryJointNamesAreCutInMessages) {
  const std::string name = "kn" + std::string(200, '\xff');
  const std::string message = error_of(
      small_file("\tJOINT " + name + "\n\t{\n\t\tOFFSET 0 -1 0\n\t\tCHANNELS 1 Zrotation\n\t}\n",
                 "Frames: 1\nFrame Time: 0.1\n0 0 0 0 0 0 " + std::string(100, '\xfe') + "\n"));
  EXPECT_TRUE(message.starts_with("bad.bvh: line 15: frame 0 value 6 (Zrotation of kn\\xff\\xff"))
      << message;
  EXPECT_NE(message.find("... (cut)) '\\xfe"), std::string::npos) << message;
  EXPECT_LT(message.size(), 800u);
}

TEST(Bvh, MalformedFilesEachGetOneClearError) {
  ASSERT_EQ(read_bvh(small_file(), "ok.bvh")->frame_count(), 2);
  ASSERT_EQ(read_bvh("\xEF\xBB\xBF" + small_file(), "bom.bvh")->frame_count(), 2);
  EXPECT_EQ(error_of(""), "bad.bvh: the file is empty");
  EXPECT_EQ(error_of("\r\n  \n# only a comment\n"), "bad.bvh: the file is empty");
  EXPECT_EQ(error_of(small_file("\tJOINT knee\n\t\tOFFSET 0 -1 0\n\t}\n")),
            "bad.bvh: line 7: expected '{' after JOINT knee, got 'OFFSET'");
  EXPECT_EQ(error_of(small_file("\tJOINT knee\n\t{\n\t\tOFFSET 0 -1 0\n\t\tCHANNELS 1 "
                                "Zrotation\n")),
            "bad.bvh: line 11: MOTION comes before the expected '}' to close ROOT hip (opened "
            "on line 2)");
  EXPECT_EQ(error_of(small_file("", "Frames: 2\nFrame Time: 0.1\n0 0 0 0 0 0\n0 0 0 0 0\n")),
            "bad.bvh: line 11: frame 1 has 5 values, the hierarchy declares 6 channels");
  EXPECT_EQ(error_of(small_file("", "Frames: 2\nFrame Time: 0.1\n0 0 0 0 0 0\n0 0 nan 0 0 0\n")),
            "bad.bvh: line 11: frame 1 value 2 (Zposition of hip) 'nan' is not a finite number");
  EXPECT_EQ(error_of(small_file("", "Frames: 1\nFrame Time: 0.1\n0 0 0 -inf 0 0\n")),
            "bad.bvh: line 10: frame 0 value 3 (Zrotation of hip) '-inf' is not a finite number");
  EXPECT_EQ(error_of(small_file("", "Frames: 1\nFrame Time: 0.1\n1e300 0 0 0 0 0\n")),
            "bad.bvh: line 10: frame 0 value 0 (Xposition of hip) '1e300' is beyond 1e+09");
  EXPECT_EQ(error_of(small_file("", "Frames: 1\nFrame Time: 0.1\n0 0 0 0 2e9 0\n")),
            "bad.bvh: line 10: frame 0 value 4 (Xrotation of hip) '2e9' is beyond 1e+09");
  EXPECT_EQ(error_of(small_file("\tJOINT knee\n\t{\n\t\tOFFSET 0 -1e300 0\n")),
            "bad.bvh: line 8: OFFSET of JOINT knee: '-1e300' is beyond 1e+09");
  // Within the range in the file, beyond it once scaled.
  const auto scaled = read_bvh(small_file("", "Frames: 1\nFrame Time: 0.1\n5e8 0 0 0 0 0\n"),
                               "bad.bvh", {.scale = 10.0});
  ASSERT_FALSE(scaled);
  EXPECT_EQ(scaled.error().message,
            "bad.bvh: line 10: frame 0 value 0 (Xposition of hip) '5e8' is beyond 1e+09 (times "
            "the scale)");
  EXPECT_EQ(error_of(small_file("", "Frames: 1\nFrame Time: 0.1\n0 0 0 1,5 0 0\n")),
            "bad.bvh: line 10: frame 0 value 3 (Zrotation of hip) '1,5' is not a number");
  EXPECT_EQ(error_of(small_file("", "Frames: 3\nFrame Time: 0.1\n0 0 0 0 0 0\n0 0 0 0 0 0\n")),
            "bad.bvh: line 8: Frames: says 3 but 2 motion lines follow");
  EXPECT_EQ(error_of(small_file("", "Frames: 1\nFrame Time: 0.1\n0 0 0 0 0 0\n0 0 0 0 0 0\n")),
            "bad.bvh: line 8: Frames: says 1 but 2 motion lines follow");
  EXPECT_EQ(error_of(small_file("\tJOINT knee\n\t{\n\t\tOFFSET 0 -1 0\n\t\tCHANNELS 3 Zrotation "
                                "Xrot Yrotation\n\t}\n")),
            "bad.bvh: line 9: unknown channel 'Xrot' in JOINT knee (expected Xposition, "
            "Yposition, Zposition, Xrotation, Yrotation or Zrotation)");
  EXPECT_EQ(error_of(small_file("\tJOINT knee\n\t{\n\t\tOFFSET 0 -1 0\n\t\tCHANNELS 3 Zrotation "
                                "Xrotation\n\t}\n")),
            "bad.bvh: line 9: CHANNELS of JOINT knee says 3 but lists 2");
  EXPECT_EQ(error_of(small_file("\tJOINT knee\n\t{\n\t\tOFFSET 0 -1 0\n\t\tCHANNELS 2 Zrotation "
                                "Zrotation\n\t}\n")),
            "bad.bvh: line 9: JOINT knee lists Zrotation twice");
  EXPECT_EQ(error_of(small_file("\tJOINT knee\n\t{\n\t\tOFFSET 0 nan 0\n")),
            "bad.bvh: line 8: OFFSET of JOINT knee: 'nan' is not a finite number");
  EXPECT_EQ(error_of(small_file("\tJOINT hip\n\t{\n\t\tOFFSET 0 -1 0\n\t\tCHANNELS 0\n\t}\n")),
            "bad.bvh: line 6: a second joint is named 'hip' (the first is on line 2)");
  EXPECT_EQ(error_of(small_file("\tJOINT kn#ee\n\t{\n\t\tOFFSET 0 -1 0\n\t}\n")),
            "bad.bvh: line 6: joint name 'kn#ee' holds a brace or '#', which a BVH name cannot");
  EXPECT_EQ(error_of(small_file("\tJOINT knee\n\t{\n\t\tOFFSET 0 -1 0\n\t\tCHANNELS 0\n\t\tEnd "
                                "Site\n\t\t{\n\t\t\tOFFSET 0 -1 0\n\t\t\tJOINT toe\n")),
            "bad.bvh: line 13: unexpected 'JOINT' in End Site of knee (expected '}'; End Sites "
            "have no children)");
  EXPECT_EQ(error_of(small_file("\tJOINT kn\x1b[2Jee\n\t\tOFFSET 0 -1 0\n\t}\n")),
            "bad.bvh: line 7: expected '{' after JOINT kn\\x1b[2Jee, got 'OFFSET'");
  // Truncated: the file stops inside the hierarchy, or inside the motion.
  const std::string whole = small_file();
  EXPECT_EQ(error_of(whole.substr(0, whole.find("\t\tEnd Site"))),
            "bad.bvh: line 9: the file ends before the expected '}' to close JOINT knee (opened "
            "on line 6)");
  EXPECT_EQ(error_of(whole.substr(0, whole.size() - 8)),
            "bad.bvh: line 20: frame 1 has 5 values, the hierarchy declares 9 channels");
  EXPECT_EQ(error_of(whole.substr(0, whole.find("Frames:"))),
            "bad.bvh: line 16: the file ends after MOTION; expected 'Frames: <count>'");
  EXPECT_EQ(error_of("ROOT hip\n{\n"), "bad.bvh: line 1: expected HIERARCHY, got 'ROOT'");
  EXPECT_EQ(error_of(small_file("", "Frames: 0\nFrame Time: 0\n")),
            "bad.bvh: line 9: Frame Time must be a finite number of seconds > 0, got '0'");
  EXPECT_EQ(error_of(small_file("", "Frames: -1\nFrame Time: 0.1\n")),
            "bad.bvh: line 8: expected 'Frames: <count>', got 'Frames: -1'");
}

// An independent evaluation of a BVH file for the FK test: its own token walk and 4x4
// matrices built with AngleAxis from the raw numbers, none of the library's BVH or Euler code.
struct RawJoint {
  int parent;
  Eigen::Vector3d offset;
  std::vector<std::string> channels;
};

std::vector<Eigen::Vector3d> raw_positions(const std::string& text, int frame) {
  std::istringstream in(text);
  std::vector<RawJoint> joints;
  std::vector<int> open;
  std::string word;
  while (in >> word && word != "MOTION") {
    if (word == "ROOT" || word == "JOINT" || word == "End") {
      in >> word;  // the name, or "Site"
      joints.push_back({open.empty() ? -1 : open.back(), Eigen::Vector3d::Zero(), {}});
      open.push_back(static_cast<int>(joints.size()) - 1);
    } else if (word == "OFFSET") {
      in >> joints.back().offset.x() >> joints.back().offset.y() >> joints.back().offset.z();
    } else if (word == "CHANNELS") {
      int n = 0;
      in >> n;
      joints.back().channels.resize(n);
      for (auto& c : joints.back().channels) in >> c;
    } else if (word == "}") {
      open.pop_back();
    }
  }
  int frames = 0, total = 0;
  double frame_time = 0;
  in >> word >> frames >> word >> word >> frame_time;
  for (const auto& j : joints) total += static_cast<int>(j.channels.size());
  std::vector<double> values(total);
  for (int f = 0; f <= frame; ++f) {
    for (double& v : values) in >> v;
  }
  std::vector<Eigen::Matrix4d> world(joints.size());
  std::vector<Eigen::Vector3d> positions;
  int column = 0;
  for (std::size_t j = 0; j < joints.size(); ++j) {
    Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
    local.block<3, 1>(0, 3) = joints[j].offset;
    for (const std::string& c : joints[j].channels) {
      const double v = values[column++];
      const int axis = c[0] - 'X';
      if (c.substr(1) == "position") {
        local(axis, 3) = v;
      } else {
        Eigen::Matrix4d r = Eigen::Matrix4d::Identity();
        r.block<3, 3>(0, 0) =
            Eigen::AngleAxisd(v * std::numbers::pi / 180, Eigen::Vector3d::Unit(axis)).matrix();
        local = local * r;
      }
    }
    world[j] = joints[j].parent < 0 ? local : Eigen::Matrix4d(world[joints[j].parent] * local);
    positions.push_back(world[j].block<3, 1>(0, 3));
  }
  return positions;
}

TEST(Bvh, WalkForwardKinematicsMatchesAnIndependentEvaluation) {
  ASSERT_TRUE(std::filesystem::exists(kWalk)) << kWalk << " not found";
  const auto clip = read_bvh_file(kWalk);
  ASSERT_TRUE(clip) << clip.error().message;
  EXPECT_EQ(clip->frame_count(), 994);
  EXPECT_EQ(clip->joint_count(), 31 + 7);  // 31 joints and 7 End Sites
  EXPECT_EQ(clip->channel_count(), 96);
  EXPECT_NEAR(clip->frame_time, 0.0083333, 1e-15);
  EXPECT_EQ(clip->skeleton.names[3], "LeftKnee");
  EXPECT_DOUBLE_EQ(clip->motion(0, 2), -33.8986);
  const std::string text = testing_support::read_file(kWalk);
  for (const int frame : {0, 1, 250, 600, 993}) {
    const std::vector<Eigen::Vector3d> expected = raw_positions(text, frame);
    const SkeletonPose pose = pose_of(*clip, frame);
    ASSERT_EQ(expected.size(), pose.global_positions.size());
    for (std::size_t j = 0; j < expected.size(); ++j) {
      EXPECT_LT((pose.global_positions[j] - expected[j]).norm(), 1e-9)
          << "frame " << frame << " joint " << clip->skeleton.names[j];
    }
  }
}

TEST(Bvh, WalkWrittenToAFileAndReadBackIsTheSame) {
  ASSERT_TRUE(std::filesystem::exists(kWalk)) << kWalk << " not found";
  const BvhClip clip = *read_bvh_file(kWalk, {.scale = 0.056444});
  const auto path = testing_support::fresh_dir("bvh_walk") / "walk.bvh";
  ASSERT_TRUE(write_bvh_file(path, clip));
  const auto back = read_bvh_file(path);
  ASSERT_TRUE(back) << back.error().message;
  expect_same_clip(clip, *back);
}

TEST(Bvh, WalkPosesSetAsFramesKeepTheirPositions) {
  ASSERT_TRUE(std::filesystem::exists(kWalk)) << kWalk << " not found";
  BvhClip clip = *read_bvh_file(kWalk);
  for (const int frame : {0, 400, 993}) {
    const SkeletonPose before = pose_of(clip, frame);
    bvh_pose_to_frame(before, clip, frame);
    const SkeletonPose after = pose_of(clip, frame);
    for (int j = 0; j < clip.joint_count(); ++j) {
      EXPECT_LT((before.global_positions[j] - after.global_positions[j]).norm(), 1e-9);
    }
  }
}

// Indentation stops deepening at 32 tabs: a 20,000-deep chain indented in full would be 1.6 GB
// of tabs; its file stays about 4 MB and reads back the same.
TEST(Bvh, ADeepChainIsWrittenInLinearSize) {
  BvhClip chain;
  const int depth = 20000;
  for (int j = 0; j < depth; ++j)
    chain.skeleton.add_joint("j" + std::to_string(j), j - 1, Vec3(0, 1, 0));
  chain.channels.assign(depth, {BvhChannel::z_rotation});
  chain.end_sites.assign(depth, false);
  chain.motion = Eigen::MatrixXd::Zero(1, depth);
  const std::string text = write_bvh(chain);
  EXPECT_LT(text.size(), 5'000'000u);
  const auto back = read_bvh(text, "deep.bvh");
  ASSERT_TRUE(back) << back.error().message;
  EXPECT_EQ(back->skeleton.parents, chain.skeleton.parents);
}

TEST(Bvh, WritingRefusesClipsAFileCannotHold) {
  BvhClip clip = read_ok(kOddClip);
  clip.skeleton.names[1] = "left arm";
  const auto dir = testing_support::fresh_dir("bvh_refused");
  const auto written = write_bvh_file(dir / "x.bvh", clip);
  ASSERT_FALSE(written);
  EXPECT_EQ(written.error().message,
            (dir / "x.bvh").string() +
                ": cannot write this clip: joint 1 name 'left arm' has whitespace, a brace or "
                "'#', which a BVH file cannot hold");
  EXPECT_FALSE(std::filesystem::exists(dir / "x.bvh"));
  clip = read_ok(kOddClip);
  clip.motion(2, 3) = std::nan("");
  EXPECT_EQ(clip.validate()->message, "motion value 3 of frame 2 is not finite");
  clip = read_ok(kOddClip);
  clip.channels[3].push_back(BvhChannel::x_rotation);
  EXPECT_EQ(clip.validate()->message, "End Site hand_End has channels");
}

}  // namespace
}  // namespace animkit
