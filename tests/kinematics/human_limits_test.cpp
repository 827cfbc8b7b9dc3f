#include "animkit/kinematics/human_limits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/kinematics/tree_ik.h"
#include "cmu_walk.h"

namespace animkit {
namespace {

using testing_support::CmuWalk;
using testing_support::load_cmu_walk;

TEST(HumanLimits, KneesAndElbowsAreHingesRootsFreeTheRestBalls) {
  const CmuWalk walk = load_cmu_walk();
  const Skeleton& s = walk.skeleton;
  const auto limits = human_joint_limits(s);
  ASSERT_EQ(static_cast<int>(limits.size()), s.joint_count());
  for (int j = 0; j < s.joint_count(); ++j) {
    const std::string& name = s.names()[j];
    if (s.parents()[j] < 0) {
      EXPECT_TRUE(std::holds_alternative<FreeJoint>(limits[j])) << name;
    } else if (name.find("Knee") != std::string::npos || name.find("Elbow") != std::string::npos) {
      EXPECT_TRUE(std::holds_alternative<HingeLimit>(limits[j])) << name;
    } else {
      EXPECT_TRUE(std::holds_alternative<BallLimit>(limits[j])) << name;
    }
    EXPECT_FALSE(validate(limits[j])) << name;
  }
}

// The shin's tip for a knee turned by `q` relative to rest, in the knee's frame.
Vec3 shin_tip(const Skeleton& s, int knee, const Quat& q) {
  const int ankle = s.child_list()[s.child_begin()[knee]];
  return q * s.rest_offsets()[ankle];
}

TEST(HumanLimits, KneesBendBackOnlyAndElbowsForwardOnly) {
  const CmuWalk walk = load_cmu_walk();
  const Skeleton& s = walk.skeleton;
  const auto limits = human_joint_limits(s);
  for (const char* name : {"LeftKnee", "RightKnee", "LeftElbow", "RightElbow"}) {
    const int j = s.find_joint(name);
    const auto& hinge = std::get<HingeLimit>(limits[j]);
    const bool knee = std::string(name).find("Knee") != std::string::npos;
    // The most flexion the limit allows moves the bone's end backwards (knee) or forwards.
    const double flexed = knee ? hinge.min_angle : hinge.max_angle;
    const Vec3 rest = shin_tip(s, j, Quat::Identity());
    const Vec3 bent = shin_tip(s, j, Quat(Eigen::AngleAxisd(flexed, hinge.axis)));
    if (knee) {
      EXPECT_LT(bent.z(), rest.z() - 0.3 * rest.norm()) << name;
    } else {
      EXPECT_GT(bent.z(), rest.z() + 0.3 * rest.norm()) << name;
    }
    // Bending the other way by 30 degrees is outside.
    const double wrong = knee ? 0.52 : -0.52;
    EXPECT_GT(violation(limits[j], Quat(Eigen::AngleAxisd(wrong, hinge.axis))), 0.4) << name;
  }
}

TEST(HumanLimits, FittingFindsTheAxisAClipBendsAHingeAbout) {
  SkeletonDesc d;
  d.add_joint("hip", -1, Vec3(0, 1, 0));
  d.add_joint("knee", 0, Vec3(0, -0.4, 0));
  d.add_joint("ankle", 1, Vec3(0, -0.4, 0));
  const Skeleton s = build_skeleton(d).value();
  auto limits = human_joint_limits(s);
  const Vec3 start = std::get<HingeLimit>(limits[1]).axis;
  EXPECT_LE((start - Vec3(-1, 0, 0)).norm(), 1e-12);  // bone -y: (-y) x z = -x
  // The clip bends the knee backwards about an axis 30 degrees off x, by -0.2 .. -1.2 rad.
  const Vec3 tilted = Vec3(-std::cos(0.5236), 0.0, std::sin(0.5236));
  SkeletalMotion m = make_motion(3, 6, 0.1);
  for (int f = 0; f < 6; ++f) {
    m.local_rotations[f * 3 + 1] = Quat(Eigen::AngleAxisd(-0.2 - 0.2 * f, tilted));
  }
  EXPECT_FALSE(fit_hinge_axes(s, m, limits));
  const auto& fitted = std::get<HingeLimit>(limits[1]);
  EXPECT_LE((fitted.axis - tilted).norm(), 1e-12);
  for (int f = 0; f < 6; ++f) {
    EXPECT_LE(violation(fitted, m.local_rotations[f * 3 + 1]), 1e-9) << f;
  }
  // A clip that never bends it leaves the axis alone.
  auto still = human_joint_limits(s);
  EXPECT_FALSE(fit_hinge_axes(s, make_motion(3, 4, 0.1), still));
  EXPECT_EQ(std::get<HingeLimit>(still[1]).axis, start);
  // A motion of another skeleton is refused, the limits left as they were.
  const auto error = fit_hinge_axes(s, make_motion(2, 4, 0.1), still);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->message,
            "fitting hinge axes: a motion of 2 joints and 3 limits for a skeleton of 3 joints");
  EXPECT_EQ(std::get<HingeLimit>(still[1]).axis, start);
}

TEST(HumanLimits, TheCapturedWalkStaysNearlyInsideOnceTheHingesAreFitted) {
  // How far the CMU walk itself goes past these rough limits, printed (a solver starting
  // from a captured frame first moves it inside them).
  const CmuWalk walk = load_cmu_walk();
  const Skeleton& s = walk.skeleton;
  auto limits = human_joint_limits(s);
  ASSERT_FALSE(fit_hinge_axes(s, walk.motion, limits));
  SkeletonPose pose = skeleton_rest_pose(s);
  std::vector<double> worst(s.joint_count(), 0.0);
  for (int f = 0; f < walk.motion.frame_count(); ++f) {
    walk.motion.read_frame(f, pose);
    for (int j = 0; j < s.joint_count(); ++j) {
      worst[j] = std::max(worst[j], violation(limits[j], relative_to_rest(s, pose, j)));
    }
  }
  double knees = 0.0, all = 0.0;
  for (int j = 0; j < s.joint_count(); ++j) {
    if (worst[j] > 0.0)
      std::printf("%s beyond its limit by %.3f rad\n", s.names()[j].c_str(), worst[j]);
    all = std::max(all, worst[j]);
    if (s.names()[j].find("Knee") != std::string::npos) knees = std::max(knees, worst[j]);
  }
  EXPECT_LT(knees, 0.05);
  EXPECT_LT(all, 0.2);
}

}  // namespace
}  // namespace animkit
