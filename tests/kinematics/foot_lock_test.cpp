// Foot locking: legs, knee flexion and the lock on the CMU walk 131_01 (skipped
// when the data is absent). Settings and contact detection: foot_contacts_test.cpp.
#pragma GCC diagnostic ignored "-Wuninitialized"  // GCC 12 AVX-512 false positive (dense Eigen)
#include "animkit/kinematics/foot_lock.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kWalk;
constexpr double kCmuMetresPerUnit = 0.056444;

TEST(FootLock, MissingLegJointsAreNamed) {
  SkeletonDesc d;
  d.add_joint("Hips", -1, Vec3::Zero());
  d.add_joint("LeftHip", 0, Vec3(0.1, 0, 0));
  d.add_joint("LeftKnee", 1, Vec3(0, -0.4, 0));
  const auto skeleton = build_skeleton(d);
  ASSERT_TRUE(skeleton);
  EXPECT_EQ(find_biped_legs(*skeleton).error().message,
            "no joint named LeftAnkle: a biped's legs are found by name (LeftHip, LeftKnee, "
            "LeftAnkle and the same on the right)");
  d.add_joint("LeftAnkle", 0, Vec3(0, -0.4, 0));
  EXPECT_EQ(find_biped_legs(*build_skeleton(d)).error().message,
            "a biped's leg needs LeftKnee to be the parent of LeftAnkle");
}

TEST(FootLock, KneeFlexionIsSignedByTheForwardSide) {
  const Vec3 hip(0, 1, 0), ankle(0, 0, 0);
  EXPECT_NEAR(knee_flexion(hip, Vec3(0, 0.5, 0.5), ankle, Vec3::UnitZ()), M_PI / 2, 1e-12);
  EXPECT_NEAR(knee_flexion(hip, Vec3(0, 0.5, -0.5), ankle, Vec3::UnitZ()), -M_PI / 2, 1e-12);
  EXPECT_NEAR(knee_flexion(hip, Vec3(0, 0.5, 0), ankle, Vec3::UnitZ()), 0.0, 1e-12);
}

struct Walk {
  Skeleton skeleton;
  BipedLegs legs;
  SkeletalMotion motion;
};

// The walk in metres, read once for the whole suite; null when the data is absent.
const Walk* walk() {
  static const std::optional<Walk> loaded = []() -> std::optional<Walk> {
    if (!std::filesystem::exists(kWalk)) return std::nullopt;
    auto clip = read_bvh_file(kWalk, {.scale = kCmuMetresPerUnit});
    if (!clip) return std::nullopt;
    auto skeleton = build_skeleton(clip->skeleton);
    if (!skeleton) return std::nullopt;
    auto legs = find_biped_legs(*skeleton);
    if (!legs) return std::nullopt;
    return Walk{*skeleton, *legs, motion_from_bvh(*clip)};
  }();
  return loaded ? &*loaded : nullptr;
}

// Every frame's posed skeleton (globals filled).
std::vector<SkeletonPose> pose_all(const Skeleton& skeleton, const SkeletalMotion& motion) {
  std::vector<SkeletonPose> poses(motion.frame_count(), skeleton_rest_pose(skeleton));
  for (int f = 0; f < motion.frame_count(); ++f) {
    motion.read_frame(f, poses[f]);
    skeleton_forward_kinematics(skeleton, poses[f]);
  }
  return poses;
}

class FootLockWalk : public ::testing::Test {
 protected:
  void SetUp() override {
    w = walk();
    ASSERT_NE(w, nullptr) << kWalk << " is not here";
    auto r = lock_feet(w->skeleton, w->legs, w->motion, settings, ws, locked);
    ASSERT_TRUE(r) << r.error().message;
    result = std::move(*r);
    before = pose_all(w->skeleton, w->motion);
    after = pose_all(w->skeleton, locked);
  }
  const Walk* w = nullptr;
  FootLockSettings settings;
  FootLockWorkspace ws;
  SkeletalMotion locked;
  FootLockResult result;
  std::vector<SkeletonPose> before, after;
};

TEST_F(FootLockWalk, FindsEachStepOfBothFeet) {
  // "Start Walk Stop": standing, four strides, standing. Reading the ankle trails (height and
  // XZ per 10 frames), each foot rests 8 times: the start stance, the steps, small shuffles
  // while stopping (e.g. the right foot's 355..402 and 412..440 are two placements 4 cm apart)
  // and the final stance.
  EXPECT_EQ(result.metrics.contacts[0], 8);
  EXPECT_EQ(result.metrics.contacts[1], 8);
  for (int leg = 0; leg < 2; ++leg) {
    for (const FootContactSpan& s : result.contacts[leg].spans) {
      EXPECT_GE(s.last - s.first + 1, settings.min_contact_frames);
    }
  }
}

TEST_F(FootLockWalk, PlantedFeetSlideLessThanHalfACentimetrePerFrame) {
  const FootLockMetrics& m = result.metrics;
  std::printf(
      "sliding per planted frame, cm: before mean %.4f max %.4f, after mean %.4f max %.4f\n",
      m.slide_before_mean_cm, m.slide_before_max_cm, m.slide_after_mean_cm, m.slide_after_max_cm);
  EXPECT_LT(m.slide_after_mean_cm, 0.5);
  // The max too: inside a span the ankle sits on its lock up to the IK error, and the only
  // misses are frames where the knee range or the leg's reach clamps the target.
  EXPECT_LT(m.slide_after_max_cm, 0.5);
  EXPECT_LT(m.slide_after_mean_cm, m.slide_before_mean_cm / 10);
}

TEST_F(FootLockWalk, FramesWithoutWeightAreUnchangedAndBlendsMoveTheAnkleByTheWeight) {
  int untouched = 0, blended = 0;
  for (int f = 0; f < w->motion.frame_count(); ++f) {
    const double wl = result.contacts[0].weight[f], wr = result.contacts[1].weight[f];
    for (int j = 0; j < w->skeleton.joint_count(); ++j) {
      const bool leg_joint = ws.in_leg[j] != 0;
      if ((wl == 0.0 && wr == 0.0) || !leg_joint) {
        ASSERT_LE((after[f].global_positions[j] - before[f].global_positions[j]).norm(), 1e-9)
            << "frame " << f << " joint " << w->skeleton.names()[j];
      }
    }
    if (wl == 0.0 && wr == 0.0) ++untouched;
    for (int leg = 0; leg < 2; ++leg) {
      const FootContacts& c = result.contacts[leg];
      if (c.weight[f] <= 0.0 || c.weight[f] >= 1.0) continue;
      ++blended;
      const int ankle = w->legs[leg].ankle;
      const Vec3 lock = c.lock[f], a0 = before[f].global_positions[ankle];
      // The ankle moves toward the lock by the weight's share of the way, no more.
      EXPECT_LE((after[f].global_positions[ankle] - a0).norm(),
                c.weight[f] * (lock - a0).norm() + 1e-9)
          << "frame " << f << " leg " << leg;
    }
  }
  EXPECT_GT(untouched, 50);
  EXPECT_GT(blended, 100);
}

TEST_F(FootLockWalk, KeepsBonesAnkleOrientationAndKneeRange) {
  for (int f = 0; f < w->motion.frame_count(); ++f) {
    const auto& p0 = before[f].global_positions;
    const auto& p1 = after[f].global_positions;
    for (int j = 0; j < w->skeleton.joint_count(); ++j) {
      const int parent = w->skeleton.parents()[j];
      if (parent < 0) continue;
      ASSERT_NEAR((p1[j] - p1[parent]).norm(), (p0[j] - p0[parent]).norm(), 1e-9);
    }
    const Vec3 forward = (p1[w->legs[0].hip] - p1[w->legs[1].hip]).cross(Vec3::UnitY());
    for (int leg = 0; leg < 2; ++leg) {
      const LegJoints& l = w->legs[leg];
      ASSERT_LT(
          after[f].global_rotations[l.ankle].angularDistance(before[f].global_rotations[l.ankle]),
          1e-9);
      if (result.contacts[leg].weight[f] <= 0.0) continue;
      const double flexion = knee_flexion(p1[l.hip], p1[l.knee], p1[l.ankle], forward);
      ASSERT_GE(flexion, settings.min_knee_flexion - 1e-9) << "frame " << f << " leg " << leg;
      ASSERT_LE(flexion, settings.max_knee_flexion + 1e-9) << "frame " << f << " leg " << leg;
    }
  }
}

TEST_F(FootLockWalk, BlendsAvoidThePopOfSnapping) {
  // Snapping (no blend) moves the ankle to its lock in one frame; the default blend spreads
  // the same correction over 10 frames each side, so its largest change per frame is far less.
  FootLockSettings snap = settings;
  snap.blend_frames = 0;
  SkeletalMotion out;
  const auto snapped = lock_feet(w->skeleton, w->legs, w->motion, snap, ws, out);
  ASSERT_TRUE(snapped);
  std::printf("largest correction step, cm: blend %d: %.3f, no blend: %.3f\n",
              settings.blend_frames, result.metrics.max_correction_step_cm,
              snapped->metrics.max_correction_step_cm);
  EXPECT_LT(result.metrics.max_correction_step_cm, 0.5 * snapped->metrics.max_correction_step_cm);
  EXPECT_LT(result.metrics.max_correction_step_cm, 2.0);
}

TEST_F(FootLockWalk, TheOriginalKneePoleLocksAsWell) {
  FootLockSettings original = settings;
  original.knee_pole = KneePole::original;
  SkeletalMotion out;
  const auto r = lock_feet(w->skeleton, w->legs, w->motion, original, ws, out);
  ASSERT_TRUE(r);
  EXPECT_LT(r->metrics.slide_after_mean_cm, 0.5);
  EXPECT_LT(r->metrics.slide_after_max_cm, 0.5);
}

TEST_F(FootLockWalk, IsDeterministic) {
  FootLockWorkspace other_ws;
  SkeletalMotion again;
  ASSERT_TRUE(lock_feet(w->skeleton, w->legs, w->motion, settings, other_ws, again));
  ASSERT_EQ(again.local_rotations.size(), locked.local_rotations.size());
  for (std::size_t i = 0; i < locked.local_rotations.size(); ++i) {
    ASSERT_EQ(again.local_rotations[i].coeffs(), locked.local_rotations[i].coeffs()) << i;
    ASSERT_EQ(again.local_translations[i], locked.local_translations[i]) << i;
  }
}

TEST_F(FootLockWalk, RefusesBadInputWithAMessage) {
  FootLockSettings bad;
  bad.blend_frames = -3;
  SkeletalMotion out;
  EXPECT_EQ(lock_feet(w->skeleton, w->legs, w->motion, bad, ws, out).error().message,
            "foot lock blend must be >= 0 frames, got -3");
  const SkeletalMotion one_frame = make_motion(w->skeleton.joint_count(), 1, 1.0 / 120);
  EXPECT_EQ(lock_feet(w->skeleton, w->legs, one_frame, {}, ws, out).error().message,
            "foot lock needs at least 2 frames, got 1");
  const SkeletalMotion wrong = make_motion(3, 10, 1.0 / 120);
  EXPECT_EQ(lock_feet(w->skeleton, w->legs, wrong, {}, ws, out).error().message,
            "foot lock motion has 3 joints but the skeleton " +
                std::to_string(w->skeleton.joint_count()));
  SkeletalMotion far = w->motion;
  far.local_translations[w->skeleton.joint_count() + 0] = Vec3(1e300, 0, 0);  // frame 1, root
  EXPECT_EQ(lock_feet(w->skeleton, w->legs, far, {}, ws, out).error().message,
            "foot lock motion frame 1, joint 0: translation (1e+300, 0, 0) is not finite or "
            "beyond 1e+09");
}

TEST(FootLockUnits, AWalkInOtherUnitsThanMetresFindsNoContactAndSaysSo) {
  // CMU's numbers read as metres: 14 m legs, and no ankle ever slower than 0.35 "m"/s.
  if (!std::filesystem::exists(kWalk)) GTEST_SKIP() << kWalk << " is not here";
  auto clip = read_bvh_file(kWalk);
  ASSERT_TRUE(clip);
  const Skeleton skeleton = build_skeleton(clip->skeleton).value();
  FootLockWorkspace ws;
  SkeletalMotion out;
  const auto result =
      lock_feet(skeleton, find_biped_legs(skeleton).value(), motion_from_bvh(*clip), {}, ws, out);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message,
            "no foot contact in 994 frames: no ankle stays within 0.05 m of the lowest ankle "
            "height at under 0.35 m/s; the legs are 14.2 m long (a person's are about 0.8 m): "
            "is the clip in metres?");
}

}  // namespace
}  // namespace animkit
