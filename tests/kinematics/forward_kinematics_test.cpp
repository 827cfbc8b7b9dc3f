#include "animkit/kinematics/forward_kinematics.h"

#include <gtest/gtest.h>

#include <numbers>

#include "animkit/core/quaternion_math.h"

namespace animkit {
namespace {

constexpr double kHalfPi = std::numbers::pi / 2.0;

Quat about(const Vec3& axis, double angle) {
  return Quat(Eigen::AngleAxisd(angle, axis));
}

void expect_near(const Vec3& actual, const Vec3& expected) {
  EXPECT_LT((actual - expected).norm(), 1e-14)
      << "actual (" << actual.transpose() << ") expected (" << expected.transpose() << ")";
}

class ForwardKinematics : public testing::Test {
 protected:
  Chain chain = *build_chain(lab_arm());
  Pose pose = rest_pose(chain);
};

TEST_F(ForwardKinematics, RootRotationSwingsTheWholeArm) {
  // Root turned +90 degrees about z: the arm, hanging along -y, now points along +x.
  pose.local_rotations[0] = about(Vec3::UnitZ(), kHalfPi);
  forward_kinematics(chain, pose, 0);
  expect_near(pose.global_positions[0], {0.0, 1.7, 0.0});
  expect_near(pose.global_positions[1], {0.8, 1.7, 0.0});
  expect_near(pose.global_positions[2], {1.2, 1.7, 0.0});
  expect_near(pose.global_positions[3], {1.4, 1.7, 0.0});
  expect_near(pose.global_positions[4], {2.6, 1.7, 0.0});
}

TEST_F(ForwardKinematics, RotationsComposeDownTheChain) {
  // Joint 1 turned +90 about z, joint 2 another +90 about z: bone 2 points along +x, bones
  // 3 and 4 (after two quarter turns) point along +y.
  pose.local_rotations[1] = about(Vec3::UnitZ(), kHalfPi);
  pose.local_rotations[2] = about(Vec3::UnitZ(), kHalfPi);
  forward_kinematics(chain, pose, 0);
  expect_near(pose.global_positions[1], {0.0, 0.9, 0.0});
  expect_near(pose.global_positions[2], {0.4, 0.9, 0.0});
  expect_near(pose.global_positions[3], {0.4, 1.1, 0.0});
  expect_near(pose.global_positions[4], {0.4, 2.3, 0.0});
  // global = parent * local: joint 2's world rotation is the half turn about z.
  EXPECT_NEAR(rotation_angle_between(Quat::Identity(), pose.global_rotations[2]), std::numbers::pi,
              1e-14);
}

TEST_F(ForwardKinematics, ParentRotationActsAfterChildRotation) {
  // Joint 1 turned +90 about z, joint 2 +90 about x: global[2] = global[1] * local[2], so the
  // child's x-turn applies to bone 3 first and the parent's z-turn after it.
  pose.local_rotations[1] = about(Vec3::UnitZ(), kHalfPi);
  pose.local_rotations[2] = about(Vec3::UnitX(), kHalfPi);
  forward_kinematics(chain, pose, 0);
  expect_near(pose.global_positions[2], {0.4, 0.9, 0.0});
  // (0,-0.2,0): about x -> (0,0,-0.2); about z -> (0,0,-0.2). The reversed order would give
  // (0.2,0,0) and put joint 3 at (0.6, 0.9, 0).
  expect_near(pose.global_positions[3], {0.4, 0.9, -0.2});
  expect_near(pose.global_positions[4], {0.4, 0.9, -1.4});
}

TEST_F(ForwardKinematics, OrderOfRotationsMatters) {
  // q_next = q2 * q1: rotate by q1 first, then q2. Root: x then y quarter turns.
  const Quat q1 = about(Vec3::UnitX(), kHalfPi), q2 = about(Vec3::UnitY(), kHalfPi);
  pose.local_rotations[0] = q2 * q1;
  forward_kinematics(chain, pose, 0);
  // (0,-0.8,0) turned about x by +90 -> (0,0,-0.8); then about y by +90 -> (-0.8,0,0).
  expect_near(pose.global_positions[1], {-0.8, 1.7, 0.0});
}

TEST_F(ForwardKinematics, PartialUpdateMatchesFullRecompute) {
  pose.local_rotations[0] = about(Vec3(1, 2, 3).normalized(), 0.7);
  forward_kinematics(chain, pose, 0);
  Pose partial = pose;
  partial.local_rotations[2] = about(Vec3(0, 0, 1), -1.1);
  pose.local_rotations[2] = partial.local_rotations[2];
  forward_kinematics(chain, partial, 2);
  forward_kinematics(chain, pose, 0);
  for (int i = 0; i < chain.joint_count(); ++i) {
    EXPECT_EQ(partial.global_positions[i], pose.global_positions[i]);
    EXPECT_EQ(partial.global_rotations[i].coeffs(), pose.global_rotations[i].coeffs());
  }
}

}  // namespace
}  // namespace animkit
