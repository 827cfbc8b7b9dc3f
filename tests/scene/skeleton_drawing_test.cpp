#include "animkit/scene/skeleton_drawing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace animkit {
namespace {

double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(LimitOutline, AHingeSweepsTheBoneFromMinToMaxAboutItsAxis) {
  const HingeLimit hinge{Vec3::UnitX(), -1.0, 0.5};
  const Vec3 bone(0.0, -1.0, 0.0);
  const auto rim = limit_outline(hinge, bone, 10);
  ASSERT_EQ(rim.size(), 11u);
  EXPECT_LE((rim.front() - Eigen::AngleAxisd(-1.0, Vec3::UnitX()) * bone).norm(), 1e-12);
  EXPECT_LE((rim.back() - Eigen::AngleAxisd(0.5, Vec3::UnitX()) * bone).norm(), 1e-12);
  for (const Vec3& p : rim) EXPECT_NEAR(p.x(), 0.0, 1e-12);  // in the plane across the axis
}

TEST(LimitOutline, ABallsRimIsTheConeEdgeAndEveryRimDirectionIsOnTheLimit) {
  const BallLimit ball{Vec3::UnitY(), 0.6, -0.3, 0.3};
  const auto rim = limit_outline(ball, Vec3::UnitY(), 24);
  ASSERT_EQ(rim.size(), 25u);
  for (const Vec3& p : rim) {
    EXPECT_NEAR(angle_between(p, Vec3::UnitY()), 0.6, 1e-12);
    // The swing that takes the bone there is on the cone's edge: inside, and no farther.
    const Quat swing = Quat::FromTwoVectors(Vec3::UnitY(), p);
    EXPECT_NEAR(violation(ball, swing), 0.0, 1e-9);
    const Quat beyond = Quat(Eigen::AngleAxisd(0.65, Eigen::AngleAxisd(swing).axis()));
    EXPECT_GT(violation(ball, beyond), 0.04);
  }
  EXPECT_TRUE(limit_outline(FreeJoint{}, Vec3::UnitY(), 8).empty());
}

TEST(LimitOutline, AnEllipticalConeReachesEachHalfAngleAboutItsAxis) {
  BallLimit ball{Vec3::UnitY(), 0.8, -1.0, 1.0};
  ball.swing_axis = Vec3::UnitX();
  ball.swing_angle_2 = 0.3;
  const auto rim = limit_outline(ball, Vec3::UnitY(), 4);
  EXPECT_NEAR(angle_between(rim[0], Vec3::UnitY()), 0.8, 1e-12);  // about swing_axis
  EXPECT_NEAR(angle_between(rim[1], Vec3::UnitY()), 0.3, 1e-12);  // about y x x
}

SkeletonDesc three_joints() {
  SkeletonDesc d;
  const int root = d.add_joint("root", -1, Vec3(0, 1, 0));
  const int on_root = d.add_joint("on_root", root, Vec3::Zero());
  d.add_joint("tip", on_root, Vec3(0, 0.5, 0));
  return d;
}

TEST(DescribeSkeleton, BonesAndJointsButNothingForAJointOnItsParent) {
  const Skeleton s = build_skeleton(three_joints()).value();
  const SkeletonPose pose = skeleton_rest_pose(s);
  DrawList all;
  SkeletonStyle style;
  describe_skeleton(all, s, pose, style);
  // One bone (on_root -> tip) and two spheres (root, tip): the zero bone draws nothing.
  DrawList expected;
  expected.add_bone_box(Vec3(0, 1, 0), Vec3(0, 1.5, 0), style.bone_thickness, style.bone);
  expected.add_sphere(Vec3(0, 1, 0), style.joint_radius, style.joint, 10, 6);
  expected.add_sphere(Vec3(0, 1.5, 0), style.joint_radius, style.joint, 10, 6);
  EXPECT_EQ(all.triangles.size(), expected.triangles.size());
  EXPECT_LE((all.bounds().max() - expected.bounds().max()).norm(), 1e-6);
}

TEST(DescribeJointLimit, TheArcIsAroundTheJointAtTheRadiusInItsParentsFrame) {
  const Skeleton s = build_skeleton(three_joints()).value();
  SkeletonPose pose = skeleton_rest_pose(s);
  // Turn the root a quarter turn about z: the limit turns with it.
  pose.local_rotations[0] = Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitZ()));
  skeleton_forward_kinematics(s, pose);
  DrawList out;
  describe_joint_limit(out, s, pose, 1, HingeLimit{Vec3::UnitX(), 0.0, 1.0}, 0.2);
  ASSERT_FALSE(out.lines.empty());
  const Vec3f joint = pose.global_positions[1].cast<float>();
  int rim = 0;
  for (const LineSegment& line : out.lines) {
    if (line.width_px != 2.5f || line.color.r != kLimitColor.r) continue;
    ++rim;
    EXPECT_NEAR((line.a - joint).norm(), 0.2f, 1e-5f);
  }
  EXPECT_EQ(rim, 48);
  // The bone now: the tip direction (turned to -x by the root), white.
  const LineSegment& now = out.lines.back();
  EXPECT_EQ(now.color.g, kBoneNowColor.g);
  EXPECT_LE((now.b - joint - Vec3f(-0.2f, 0.0f, 0.0f)).norm(), 1e-5f);
  DrawList none;
  describe_joint_limit(none, s, pose, 1, FreeJoint{}, 0.2);
  EXPECT_TRUE(none.empty());
}

}  // namespace
}  // namespace animkit
