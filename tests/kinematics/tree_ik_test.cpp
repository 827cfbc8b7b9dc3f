// The shared tree IK vocabulary (tree_ik.h): validation messages, errors, reach.
#include "animkit/kinematics/tree_ik.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "tree_ik_samples.h"

namespace animkit {
namespace {

std::string error_of(const Skeleton& s, std::vector<Effector> effectors,
                     std::vector<JointLimit> limits = {}) {
  const SkeletonPose pose = skeleton_rest_pose(s);
  const auto error = validate_tree_ik(s, TreeIkProblem{effectors, limits}, pose);
  return error ? error->message : "(no error)";
}

TEST(TreeIk, ValidationNamesTheFirstProblem) {
  const Skeleton s = tree_samples::figure();
  const int hand = s.find_joint("l_hand");
  EXPECT_EQ(error_of(s, {}), "IK needs at least one effector");
  EXPECT_EQ(error_of(s, {Effector{99, Vec3::Zero()}}),
            "effector 0 names joint 99, the skeleton has joints 0 to 15");
  EXPECT_EQ(error_of(s, {Effector{hand, Vec3::Zero()}, Effector{hand, Vec3::Ones()}}),
            "effector 1: joint l_hand has two effectors");
  EXPECT_EQ(error_of(s, {Effector{hand, Vec3(std::numeric_limits<double>::infinity(), 0, 0)}}),
            "effector 0 (l_hand): the target position must be finite and within 1e9");
  EXPECT_EQ(error_of(s, {Effector{hand, Vec3::Zero(), Quat(2, 0, 0, 0)}}),
            "effector 0 (l_hand): the target orientation must be a unit quaternion");
  EXPECT_EQ(error_of(s, {Effector{hand, Vec3::Zero(), std::nullopt, 0.0}}),
            "effector 0 (l_hand): the weight must be > 0, got 0");
  std::vector<JointLimit> limits(16, FreeJoint{});
  limits[3] = HingeLimit{Vec3::UnitZ(), 1.0, -1.0};
  EXPECT_EQ(error_of(s, {Effector{hand, Vec3::Zero()}}, limits).rfind("joint head's limit: ", 0),
            0u);
  EXPECT_EQ(error_of(s, {Effector{hand, Vec3::Zero()}}), "(no error)");
}

TEST(TreeIk, ReachCountsTheRootsChildBones) {
  // The lab's arm: root at (0, 1.7, 0), reach 2.6 including the root's own bone, which the
  // tree solvers turn (the root joint turns, it never moves).
  const Skeleton s = build_skeleton(skeleton_desc_from_chain(lab_arm())).value();
  const SkeletonPose pose = skeleton_rest_pose(s);
  const int end = s.joint_count() - 1;
  const std::vector<Effector> near{Effector{end, Vec3(2.5, 1.7, 0)}};
  const std::vector<Effector> far{Effector{end, Vec3(2.7, 1.7, 0)}};
  EXPECT_TRUE(tree_ik_reachable(s, pose, near));
  EXPECT_FALSE(tree_ik_reachable(s, pose, far));
}

TEST(TreeIk, ErrorsAreTheLargestOverTheEffectors) {
  const Skeleton s = tree_samples::figure();
  SkeletonPose pose = skeleton_rest_pose(s);
  const int hand = s.find_joint("l_hand"), foot = s.find_joint("r_foot");
  const Vec3 at_hand = pose.global_positions[static_cast<std::size_t>(hand)];
  const Vec3 at_foot = pose.global_positions[static_cast<std::size_t>(foot)];
  const Quat turned(Eigen::AngleAxisd(0.25, Vec3::UnitY()));
  const std::vector<Effector> effectors{Effector{hand, at_hand + Vec3(0, 0.3, 0), turned},
                                        Effector{foot, at_foot + Vec3(0.1, 0, 0)}};
  const TreeIkErrors errors = tree_ik_errors(pose, effectors);
  EXPECT_NEAR(errors.position, 0.3, 1e-15);
  EXPECT_NEAR(errors.orientation, 0.25, 1e-12);
}

}  // namespace
}  // namespace animkit
