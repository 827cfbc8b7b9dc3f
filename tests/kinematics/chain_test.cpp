#include "animkit/kinematics/chain.h"

#include <gtest/gtest.h>

#include <limits>

namespace animkit {
namespace {

std::string build_error(const ChainDesc& desc) {
  const auto chain = build_chain(desc);
  return chain ? std::string("(built)") : chain.error().message;
}

TEST(Chain, LabArmHasTheLabsBonesAndReach) {
  const auto chain = build_chain(lab_arm());
  ASSERT_TRUE(chain);
  ASSERT_EQ(chain->joint_count(), 5);
  const double lengths[] = {0.0, 0.8, 0.4, 0.2, 1.2};
  for (int i = 0; i < 5; ++i) EXPECT_NEAR(chain->bone_lengths()[i], lengths[i], 1e-15);
  EXPECT_NEAR(chain->reach(), 2.6, 1e-15);
  EXPECT_EQ(chain->min_reach(),
            0.0);  // 1.2 < 0.8 + 0.4 + 0.2: every point near the root is reachable
  EXPECT_EQ(chain->root_position(), Vec3(0.0, 1.7, 0.0));
}

TEST(Chain, MinReachWhenOneBoneIsLongerThanTheRest) {
  const Vec3 rest[] = {{0, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  const auto chain = build_chain(ChainDesc::from_rest_positions(rest));
  ASSERT_TRUE(chain);
  EXPECT_NEAR(chain->min_reach(), 2.0, 1e-15);
}

TEST(Chain, RejectsFewerThanTwoJoints) {
  EXPECT_EQ(build_error(ChainDesc{}), "a chain needs at least 2 joints, got 0");
  EXPECT_EQ(build_error(ChainDesc{{Vec3(0, 1, 0)}, {}}), "a chain needs at least 2 joints, got 1");
}

TEST(Chain, RejectsZeroLengthBone) {
  ChainDesc desc = lab_arm();
  desc.local_offsets[3] = Vec3::Zero();
  EXPECT_EQ(build_error(desc), "bone 3 has zero length");
}

TEST(Chain, RejectsNonFiniteOffsets) {
  ChainDesc desc = lab_arm();
  desc.local_offsets[2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(build_error(desc), "joint 2 offset has a non-finite coordinate (0, nan, 0)");
  desc = lab_arm();
  desc.local_offsets[0].x() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(build_error(desc), "joint 0 offset has a non-finite coordinate (inf, 1.7, 0)");
}

TEST(Chain, RejectsNonUnitRotation) {
  ChainDesc desc = lab_arm();
  desc.local_rotations.assign(5, Quat::Identity());
  desc.local_rotations[1] = Quat(0.9, 0.0, 0.0, 0.0);
  EXPECT_EQ(build_error(desc), "joint 1 rotation is not a unit quaternion (norm 0.9)");
}

TEST(Chain, RejectsRotationCountMismatch) {
  ChainDesc desc = lab_arm();
  desc.local_rotations.assign(3, Quat::Identity());
  EXPECT_EQ(build_error(desc), "local_rotations has 3 entries for 5 joints");
}

TEST(Chain, RestPoseReproducesTheRestPositions) {
  const auto chain = build_chain(lab_arm());
  ASSERT_TRUE(chain);
  const Pose pose = rest_pose(*chain);
  const Vec3 expected[] = {{0, 1.7, 0}, {0, 0.9, 0}, {0, 0.5, 0}, {0, 0.3, 0}, {0, -0.9, 0}};
  for (int i = 0; i < 5; ++i) EXPECT_LT((pose.global_positions[i] - expected[i]).norm(), 1e-15);
}

}  // namespace
}  // namespace animkit
