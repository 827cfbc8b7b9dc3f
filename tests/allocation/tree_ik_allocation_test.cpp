// Each solver has its own settings struct and a caller-owned workspace, so that nothing
// allocates per call. Once a workspace has seen a skeleton and a problem shape, every
// further solve (and the two-bone solver always) makes no heap allocation at all.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "../kinematics/tree_ik_samples.h"
#include "animkit/core/symmetric_eigen.h"
#include "animkit/kinematics/tree_ik_solver.h"
#include "animkit/kinematics/two_bone_ik.h"
#include "counting_malloc.h"

namespace animkit {
namespace {

using testing::AllocationCount;
using namespace tree_samples;

// Where the buffers below escape to: a compiler may leave out an allocation whose memory
// nothing reads (clang 16 at -O3 removes such a new/delete or malloc/free pair).
double* volatile escaped_buffer = nullptr;

TEST(TreeIkAllocation, CountingSeesAllocations) {
  // The counter itself must work, or the tests below could not fail.
  AllocationCount count;
  std::vector<double> v(100);
  Eigen::MatrixXd m(7, 9);
  escaped_buffer = v.data();
  escaped_buffer = m.data();
  EXPECT_GE(count.value(), 2u);
}

// One problem shape (effector count, orientation targets) per run: DlsWorkspace sizes its
// matrices by it, so a solve after a shape change may allocate once (dls_tree.h).
TEST(TreeIkAllocation, SolvesWithAWarmWorkspaceAllocateNothing) {
  const Skeleton s = figure();
  const std::vector<int> joints = joints_named(s, {"l_hand", "r_hand", "l_foot", "r_foot"});
  for (const bool hinges : {false, true}) {
    const std::vector<JointLimit> limits = body_limits(s, hinges);
    for (const bool oriented : {false, true}) {
      for (const TreeIkSolverKind kind : all_tree_ik_solvers()) {
        std::mt19937_64 rng(12);
        TreeIkSolvers solvers;
        SkeletonPose pose = skeleton_rest_pose(s);
        for (int trial = 0; trial < 12; ++trial) {
          const SkeletonPose target = random_pose(s, limits, rng, 1.0);
          const std::vector<Effector> effectors = effectors_at(target, joints, oriented);
          const TreeIkProblem problem{effectors, limits};
          std::size_t made = 0;
          Result<TreeIkResult> result;
          {
            AllocationCount count;
            result = solve_tree_ik(kind, s, problem, solvers, pose);
            made = count.value();
          }
          ASSERT_TRUE(result);
          if (trial == 0) continue;  // the first solve sizes the workspace
          EXPECT_EQ(made, 0u) << to_string(kind) << (hinges ? " with hinges" : " with balls")
                              << (oriented ? ", oriented" : "") << ", trial " << trial;
        }
      }
    }
  }
}

TEST(TreeIkAllocation, SymmetricEigenOfAnUnchangedSizeAllocatesNothing) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(12, 12);
  a = (a + a.transpose()).eval();
  SymmetricEigen eigen;
  eigen.compute(a);  // sizes its matrices
  a(3, 4) = a(4, 3) = 0.25;
  AllocationCount count;
  eigen.compute(a);
  EXPECT_EQ(count.value(), 0u);
}

TEST(TreeIkAllocation, TwoBoneSolvesAllocateNothing) {
  TwoBoneInput input;
  input.root = Vec3(0, 1, 0);
  input.middle = Vec3(0, 0.55, 0.02);
  input.end = Vec3(0, 0.1, 0);
  input.target = Vec3(0.1, 0.3, 0.1);
  input.pole = Vec3(0, 0.55, 1);
  AllocationCount count;
  const auto result = solve_two_bone(input);
  EXPECT_EQ(count.value(), 0u);
  EXPECT_TRUE(result);
}

// solve_tree_ik() (tree_ik_solver.h), as the CLI's --solver switch uses it: one TreeIkSolvers
// warmed once per solver, then the solvers taken in turn (DLS and SDLS share a workspace).
TEST(TreeIkAllocation, SolveTreeIkBySolverKindAllocatesNothingWhenWarm) {
  const Skeleton s = figure();
  const std::vector<int> joints = joints_named(s, {"l_hand", "r_hand", "l_foot", "r_foot"});
  const std::vector<JointLimit> limits = body_limits(s, true);
  std::mt19937_64 rng(5);
  TreeIkSolvers solvers;
  SkeletonPose pose = skeleton_rest_pose(s);
  for (int trial = 0; trial < 24; ++trial) {
    const TreeIkSolverKind kind = all_tree_ik_solvers()[static_cast<std::size_t>(trial) % 4];
    const SkeletonPose target = random_pose(s, limits, rng, 1.0);
    const std::vector<Effector> effectors = effectors_at(target, joints, false);
    std::size_t made = 0;
    Result<TreeIkResult> result;
    {
      AllocationCount count;
      result = solve_tree_ik(kind, s, TreeIkProblem{effectors, limits}, solvers, pose);
      made = count.value();
    }
    ASSERT_TRUE(result);
    if (trial < 4) continue;  // the first solve of each kind sizes its workspace
    EXPECT_EQ(made, 0u) << to_string(kind) << ", trial " << trial;
  }
}

}  // namespace
}  // namespace animkit
