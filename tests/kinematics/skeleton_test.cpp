#include "animkit/kinematics/skeleton.h"

#include <gtest/gtest.h>

#include <limits>
#include <numbers>
#include <random>

#include "animkit/kinematics/forward_kinematics.h"

namespace animkit {
namespace {

std::string error_of(const SkeletonDesc& desc) {
  const auto error = desc.validate();
  const auto built = build_skeleton(desc);
  EXPECT_FALSE(built);
  if (!error || built) return "(no error)";
  EXPECT_EQ(built.error().message, error->message);
  return error->message;
}

// A small tree: pelvis with two legs (hip -> knee) and a spine.
SkeletonDesc small_tree() {
  SkeletonDesc d;
  d.add_joint("pelvis", -1, {0, 1, 0});
  d.add_joint("lhip", 0, {0.1, 0, 0});
  d.add_joint("lknee", 1, {0, -0.5, 0});
  d.add_joint("rhip", 0, {-0.1, 0, 0});
  d.add_joint("rknee", 3, {0, -0.5, 0});
  d.add_joint("spine", 0, {0, 0.3, 0});
  return d;
}

TEST(Skeleton, BuildsChildrenLeavesRootsAndBoneLengths) {
  const auto s = build_skeleton(small_tree());
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_EQ(s->joint_count(), 6);
  EXPECT_EQ(s->roots(), std::vector<int>{0});
  EXPECT_EQ(s->leaves(), (std::vector<int>{2, 4, 5}));
  EXPECT_EQ(s->child_count(0), 3);
  EXPECT_EQ(std::vector<int>(s->child_list().begin() + s->child_begin()[0],
                             s->child_list().begin() + s->child_begin()[1]),
            (std::vector<int>{1, 3, 5}));
  EXPECT_EQ(s->child_count(2), 0);
  EXPECT_DOUBLE_EQ(s->bone_lengths()[0], 0.0);
  EXPECT_DOUBLE_EQ(s->bone_lengths()[2], 0.5);
  EXPECT_EQ(s->find_joint("rknee"), 4);
  EXPECT_EQ(s->find_joint("nose"), -1);
}

TEST(Skeleton, ForwardKinematicsFollowsParentsNotIndices) {
  const Skeleton s = *build_skeleton(small_tree());
  SkeletonPose pose = skeleton_rest_pose(s);
  EXPECT_LT((pose.global_positions[4] - Vec3(-0.1, 0.5, 0)).norm(), 1e-15);
  // Bend the right hip 90 degrees about x: the right knee swings forward (+z), the left stays.
  pose.local_rotations[3] = Quat(Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitX()));
  pose.local_translations[0] = Vec3(1, 1, 0);  // root translation
  skeleton_forward_kinematics(s, pose);
  EXPECT_LT((pose.global_positions[4] - Vec3(0.9, 1, -0.5)).norm(), 1e-15);
  EXPECT_LT((pose.global_positions[2] - Vec3(1.1, 0.5, 0)).norm(), 1e-15);
  EXPECT_LT((pose.global_positions[5] - Vec3(1, 1.3, 0)).norm(), 1e-15);
}

TEST(Skeleton, EqualsChainForwardKinematicsOnRandomPoses) {
  ChainDesc chain_desc = lab_arm();
  chain_desc.local_rotations.assign(5, Quat(Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized())));
  const Chain chain = *build_chain(chain_desc);
  const auto skeleton = build_skeleton(skeleton_desc_from_chain(chain_desc));
  ASSERT_TRUE(skeleton) << skeleton.error().message;
  EXPECT_EQ(skeleton->leaves(), std::vector<int>{4});
  std::mt19937 rng(12);
  std::normal_distribution<double> normal;
  Pose pose = rest_pose(chain);
  SkeletonPose tree_pose = skeleton_rest_pose(*skeleton);
  for (int trial = 0; trial < 50; ++trial) {
    for (int i = 0; i < chain.joint_count(); ++i) {
      const Quat q = Quat(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
      pose.local_rotations[i] = q;
      tree_pose.local_rotations[i] = q;
    }
    forward_kinematics(chain, pose, 0);
    skeleton_forward_kinematics(*skeleton, tree_pose);
    for (int i = 0; i < chain.joint_count(); ++i) {
      EXPECT_LT((pose.global_positions[i] - tree_pose.global_positions[i]).norm(), 1e-14);
      EXPECT_LT(pose.global_rotations[i].angularDistance(tree_pose.global_rotations[i]), 1e-12);
    }
  }
}

TEST(Skeleton, ValidationNamesTheFirstProblem) {
  EXPECT_EQ(error_of(SkeletonDesc{}), "a skeleton needs at least 1 joint, got 0");
  SkeletonDesc d = small_tree();
  d.parents[2] = 4;
  EXPECT_EQ(error_of(d),
            "joint 2 (lknee) has parent 4; a parent must come before its child (index in [0, 2)) "
            "or be -1 for a root");
  d = small_tree();
  d.parents[1] = -2;
  EXPECT_EQ(error_of(d),
            "joint 1 (lhip) has parent -2; a parent must come before its child (index in [0, 1)) "
            "or be -1 for a root");
  d = small_tree();
  d.names[3] = "lhip";
  EXPECT_EQ(error_of(d), "joint 3 is named 'lhip' like joint 1");
  d = small_tree();
  d.names[2].clear();
  EXPECT_EQ(error_of(d), "joint 2 has an empty name");
  d = small_tree();
  d.rest_offsets[5].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of(d), "joint 5 (spine) rest offset has a non-finite coordinate (0, nan, 0)");
  d = small_tree();
  d.rest_rotations.assign(6, Quat::Identity());
  d.rest_rotations[1] = Quat(1, 1, 0, 0);
  EXPECT_EQ(error_of(d), "joint 1 (lhip) rest rotation is not a unit quaternion (norm 1.41421)");
  d.rest_rotations.pop_back();
  EXPECT_EQ(error_of(d), "rest_rotations has 5 entries for 6 joints");
  d = small_tree();
  d.parents.pop_back();
  EXPECT_EQ(error_of(d), "parents has 5 entries for 6 joints");
  d = small_tree();
  d.rest_offsets.pop_back();
  EXPECT_EQ(error_of(d), "rest_offsets has 5 entries for 6 joints");
}

TEST(Skeleton, SeveralRootsAreAllowed) {
  SkeletonDesc d;
  d.add_joint("a", -1, {0, 0, 0});
  d.add_joint("b", -1, {1, 0, 0});
  d.add_joint("c", 1, {0, 1, 0});
  const auto s = build_skeleton(d);
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_EQ(s->roots(), (std::vector<int>{0, 1}));
  EXPECT_EQ(skeleton_rest_pose(*s).global_positions[2], Vec3(1, 1, 0));
}

}  // namespace
}  // namespace animkit
