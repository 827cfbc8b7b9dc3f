#include "animkit/kinematics/fabrik_tree.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "tree_ik_checks.h"

namespace animkit {
namespace {

struct Fabrik {
  using Settings = FabrikTreeSettings;
  using Workspace = FabrikTreeWorkspace;
  static Result<TreeIkResult> solve(const Skeleton& s, const TreeIkProblem& problem,
                                    const Settings& settings, Workspace& workspace,
                                    SkeletonPose& pose) {
    return solve_fabrik_tree(s, problem, settings, workspace, pose);
  }
};

// FABRIK's passes alone, without the DLS finish.
struct FabrikOnly {
  using Settings = FabrikTreeSettings;
  using Workspace = FabrikTreeWorkspace;
  static Result<TreeIkResult> solve(const Skeleton& s, const TreeIkProblem& problem,
                                    Settings settings, Workspace& workspace, SkeletonPose& pose) {
    settings.finish_with_dls = false;
    return solve_fabrik_tree(s, problem, settings, workspace, pose);
  }
};

TEST(FabrikTree, LimitsBonesAndRootsHoldOnThousandsOfRandomTargets) {
  tree_checks::limits_bones_and_roots_hold<Fabrik>(2000, 12);
}

TEST(FabrikTree, InvalidInputFailsWithItsMessage) {
  tree_checks::invalid_input_fails_with_its_message<Fabrik>();
}

TEST(FabrikTree, DeterministicAndWorkspaceReuseIsInvisible) {
  tree_checks::deterministic_and_workspace_reuse_is_invisible<Fabrik>(7);
}

// The lab's arm as a one-branch skeleton reaches what the chain's FABRIK reaches: the lab's
// shapes, one target per frame, warm-started from the previous frame as the lab drives it.
TEST(FabrikTree, LabArmReachesTheChainSolversTargets) {
  tree_checks::lab_arm_reaches_the_chain_solvers_targets<Fabrik>(IkSolverKind::fabrik);
}

TEST(FabrikTree, LimitsHoldWithoutTheDlsFinishToo) {
  tree_checks::limits_bones_and_roots_hold<FabrikOnly>(1000, 13);
}

TEST(FabrikTree, TheDlsFinishsSettingsAreValidatedWithTheirOwnMessage) {
  FabrikTreeSettings settings;
  settings.dls_finish.lambda = -1.0;
  ASSERT_TRUE(settings.validate());
  EXPECT_EQ(settings.validate()->message,
            "FABRIK's DLS finish: DLS lambda must be finite and >= 0, got -1");
  settings.finish_with_dls = false;  // unused, so not checked
  EXPECT_FALSE(settings.validate());
  const Skeleton s = tree_samples::figure();
  SkeletonPose pose = skeleton_rest_pose(s);
  const std::vector<Effector> ok{Effector{s.find_joint("l_hand"), Vec3(1, 1, 0)}};
  settings.finish_with_dls = true;
  FabrikTreeWorkspace workspace;
  const auto result = solve_fabrik_tree(s, TreeIkProblem{ok}, settings, workspace, pose);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message, settings.validate()->message);
}

// Targets made by FK of random poses inside the limits, four effectors (hands and feet, weights
// 1 to 2.5), solved from the rest pose; the fractions reached within tolerance (1e-4, 1e-3 rad).
// FABRIK with its DLS finish (the default) reaches what is asserted; the passes alone reach at
// least what they reached when the test was written, less a small margin (their misses: slow
// convergence within 100 iterations, and with hinges, fixed points of the passes short of the
// targets; see fabrik_tree.h). The hinge clamp in the backward pass took the passes alone from
// 4.5% to 56.5% with hinges on the figure and from 46.5% to 50% on the CMU skeleton; with the
// finish, the figure's hinges went from 99% to 96% (DLS starts from other fixed points).
TEST(FabrikTreeSlow, ReachesJointlyReachableTargetsOnAFigure) {
  const Skeleton s = tree_samples::figure();
  const auto joints = tree_samples::joints_named(s, {"l_hand", "r_hand", "l_foot", "r_foot"});
  const auto f = tree_checks::reach_fractions<Fabrik>(s, joints, 200);
  const auto only = tree_checks::reach_fractions<FabrikOnly>(s, joints, 200);
  RecordProperty("fractions", tree_checks::describe(f));
  RecordProperty("fractions_fabrik_only", tree_checks::describe(only));
  std::printf("FABRIK + DLS finish: %s\nFABRIK only: %s\n", tree_checks::describe(f).c_str(),
              tree_checks::describe(only).c_str());
  EXPECT_GE(f.free_default, 1.0) << tree_checks::describe(f);
  EXPECT_GE(f.free, 1.0) << tree_checks::describe(f);
  EXPECT_GE(f.oriented, 1.0) << tree_checks::describe(f);
  EXPECT_GE(f.balls, 1.0) << tree_checks::describe(f);
  EXPECT_GE(f.hinges, 0.95) << tree_checks::describe(f);
  EXPECT_GE(only.free_default, 0.83) << tree_checks::describe(only);
  EXPECT_GE(only.free, 0.97) << tree_checks::describe(only);
  EXPECT_GE(only.oriented, 0.97) << tree_checks::describe(only);
  EXPECT_GE(only.balls, 0.94) << tree_checks::describe(only);
  EXPECT_GE(only.hinges, 0.55) << tree_checks::describe(only);
}

TEST(FabrikTreeSlow, ReachesJointlyReachableTargetsOnTheCmuSkeleton) {
  const auto s = tree_samples::cmu_skeleton();
  ASSERT_TRUE(s) << "no CMU data in " ANIMKIT_TEST_DATA_DIR;
  const auto joints = tree_samples::joints_named(*s, {"lhand", "rhand", "LeftAnkle", "RightAnkle"});
  const auto f = tree_checks::reach_fractions<Fabrik>(*s, joints, 200);
  const auto only = tree_checks::reach_fractions<FabrikOnly>(*s, joints, 200);
  RecordProperty("fractions", tree_checks::describe(f));
  RecordProperty("fractions_fabrik_only", tree_checks::describe(only));
  std::printf("FABRIK + DLS finish: %s\nFABRIK only: %s\n", tree_checks::describe(f).c_str(),
              tree_checks::describe(only).c_str());
  EXPECT_GE(f.free_default, 1.0) << tree_checks::describe(f);
  EXPECT_GE(f.free, 1.0) << tree_checks::describe(f);
  EXPECT_GE(f.oriented, 1.0) << tree_checks::describe(f);
  EXPECT_GE(f.balls, 1.0) << tree_checks::describe(f);
  EXPECT_GE(f.hinges, 1.0) << tree_checks::describe(f);
  EXPECT_GE(only.free_default, 0.94) << tree_checks::describe(only);
  EXPECT_GE(only.free, 0.99) << tree_checks::describe(only);
  EXPECT_GE(only.oriented, 0.99) << tree_checks::describe(only);
  // FABRIK alone under limits is the weak baseline the DLS finish is measured against: which
  // local minimum a limited solve ends in moves with the last bits of its sums (compiler,
  // -march, how the library's files are batched), a few targets in 200 either way (measured:
  // balls 0.84, hinges 0.475 to 0.49), so these bounds leave that margin.
  EXPECT_GE(only.balls, 0.80) << tree_checks::describe(only);
  EXPECT_GE(only.hinges, 0.44) << tree_checks::describe(only);
}

}  // namespace
}  // namespace animkit
