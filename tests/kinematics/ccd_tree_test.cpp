#include "animkit/kinematics/ccd_tree.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "tree_ik_checks.h"

namespace animkit {
namespace {

struct Ccd {
  using Settings = CcdTreeSettings;
  using Workspace = CcdTreeWorkspace;
  static Result<TreeIkResult> solve(const Skeleton& s, const TreeIkProblem& problem,
                                    const Settings& settings, Workspace& workspace,
                                    SkeletonPose& pose) {
    return solve_ccd_tree(s, problem, settings, workspace, pose);
  }
};

TEST(CcdTree, LimitsBonesAndRootsHoldOnThousandsOfRandomTargets) {
  tree_checks::limits_bones_and_roots_hold<Ccd>(2000, 12);
}

TEST(CcdTree, InvalidInputFailsWithItsMessage) {
  tree_checks::invalid_input_fails_with_its_message<Ccd>();
}

TEST(CcdTree, DeterministicAndWorkspaceReuseIsInvisible) {
  tree_checks::deterministic_and_workspace_reuse_is_invisible<Ccd>(7);
}

// The lab's arm as a one-branch skeleton reaches what the chain's CCD reaches: the lab's
// shapes, one target per frame, warm-started from the previous frame as the lab drives it.
TEST(CcdTree, LabArmReachesTheChainSolversTargets) {
  tree_checks::lab_arm_reaches_the_chain_solvers_targets<Ccd>(IkSolverKind::ccd);
}

// Targets made by FK of random poses inside the limits, four effectors (hands and feet, weights
// 1 to 2.5), solved from the rest pose; the fractions reached within tolerance (1e-4, 1e-3 rad)
// are at least what this solver reached when the test was written, less a small margin (the
// misses: slow convergence within 100 iterations, and with hinges, fixed points of the passes
// short of the targets; see fabrik_tree.h).
TEST(CcdTreeSlow, ReachesJointlyReachableTargetsOnAFigure) {
  const Skeleton s = tree_samples::figure();
  const auto joints = tree_samples::joints_named(s, {"l_hand", "r_hand", "l_foot", "r_foot"});
  const auto f = tree_checks::reach_fractions<Ccd>(s, joints, 200);
  RecordProperty("fractions", tree_checks::describe(f));
  EXPECT_GE(f.free_default, 0.15) << tree_checks::describe(f);
  EXPECT_GE(f.free, 0.66) << tree_checks::describe(f);
  EXPECT_GE(f.oriented, 0.68) << tree_checks::describe(f);
  EXPECT_GE(f.balls, 0.68) << tree_checks::describe(f);
  EXPECT_GE(f.hinges, 0.29) << tree_checks::describe(f);
}

TEST(CcdTreeSlow, ReachesJointlyReachableTargetsOnTheCmuSkeleton) {
  const auto s = tree_samples::cmu_skeleton();
  ASSERT_TRUE(s) << "no CMU data in " ANIMKIT_TEST_DATA_DIR;
  const auto joints = tree_samples::joints_named(*s, {"lhand", "rhand", "LeftAnkle", "RightAnkle"});
  const auto f = tree_checks::reach_fractions<Ccd>(*s, joints, 200);
  RecordProperty("fractions", tree_checks::describe(f));
  EXPECT_GE(f.free_default, 0.24) << tree_checks::describe(f);
  EXPECT_GE(f.free, 0.74) << tree_checks::describe(f);
  EXPECT_GE(f.oriented, 0.78) << tree_checks::describe(f);
  EXPECT_GE(f.balls, 0.73) << tree_checks::describe(f);
  EXPECT_GE(f.hinges, 0.44) << tree_checks::describe(f);
}

}  // namespace
}  // namespace animkit
