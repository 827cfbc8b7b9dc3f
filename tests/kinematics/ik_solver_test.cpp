// Tests every IK solver through the one signature they share (solve_ik with a solver enum).
#include "animkit/kinematics/ik_solver.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "animkit/kinematics/drawing_session.h"
#include "animkit/kinematics/forward_kinematics.h"
#include "animkit/trajectory/lab_shapes.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kNaN;
constexpr double kInf = std::numeric_limits<double>::infinity();

class IkSolverTest : public testing::TestWithParam<IkSolverKind> {
 protected:
  Chain chain = *build_chain(lab_arm());
  Pose pose = rest_pose(chain);

  void expect_bone_lengths_kept(const Pose& p) const {
    for (int i = 1; i < chain.joint_count(); ++i) {
      EXPECT_NEAR((p.global_positions[i] - p.global_positions[i - 1]).norm(),
                  chain.bone_lengths()[i], 1e-9)
          << "bone " << i;
    }
  }
  std::string error_for(const Vec3& target, const IkOptions& options = {}) {
    const auto result = solve_ik(GetParam(), chain, pose, target, options);
    return result ? std::string("(no error)") : result.error().message;
  }
};

TEST_P(IkSolverTest, ConvergesOnEveryTargetOfEveryLabShapeWarmStarted) {
  for (LabShape shape : all_lab_shapes()) {
    DrawingOptions options;
    options.solver = GetParam();
    const auto run = run_drawing(chain, lab_shape_targets(shape), options);
    ASSERT_TRUE(run);
    for (std::size_t i = 0; i < run->frames.size(); ++i) {
      const DrawingFrame& f = run->frames[i];
      EXPECT_TRUE(f.ik.converged) << to_string(shape) << " target " << i << " error " << f.ik.error;
      EXPECT_LE(f.ik.error, 1e-4);
      EXPECT_TRUE(f.ik.reachable);
      EXPECT_LT((f.end_effector - f.target).norm(), 1e-4);
    }
  }
}

TEST_P(IkSolverTest, KeepsBoneLengthsAndLeavesAConsistentPose) {
  for (const Vec3& target : {Vec3(0.5, 0.0, 0.3), Vec3(-1.0, 0.5, 1.2), Vec3(0.1, 2.5, -0.4)}) {
    const auto result = solve_ik(GetParam(), chain, pose, target);
    ASSERT_TRUE(result);
    EXPECT_TRUE(result->converged);
    expect_bone_lengths_kept(pose);
    // Forward kinematics of the solver's rotations reproduces its positions.
    Pose replay = pose;
    forward_kinematics(chain, replay, 0);
    for (int i = 0; i < chain.joint_count(); ++i) {
      EXPECT_LT((replay.global_positions[i] - pose.global_positions[i]).norm(), 1e-12);
      EXPECT_NEAR(pose.local_rotations[i].norm(), 1.0, 1e-12);
    }
  }
}

TEST_P(IkSolverTest, ToleranceBelowRoundingStopsWithoutWreckingThePose) {
  // A tolerance no double can meet: the solver stops at rounding level instead of kicking a
  // converged chain off its solution (and never turns a good pose into a bad one).
  const auto result = solve_ik(GetParam(), chain, pose, Vec3(0.3, 0.0, 0.2),
                               IkOptions{.max_iterations = 100, .tolerance = 1e-17});
  ASSERT_TRUE(result);
  EXPECT_FALSE(result->converged);
  EXPECT_LT(result->error, 1e-13);
  expect_bone_lengths_kept(pose);
}

TEST_P(IkSolverTest, TargetJustInsideFullReachGetsTheStraightChain) {
  // At full extension both solvers crawl; within tolerance of the reach the straight chain
  // is the answer, and it counts as reachable.
  const Vec3 target = chain.root_position() + Vec3(2.6 - 5e-5, 0.0, 0.0);
  const auto result = solve_ik(GetParam(), chain, pose, target);
  ASSERT_TRUE(result);
  EXPECT_TRUE(result->reachable);
  EXPECT_TRUE(result->converged);
  EXPECT_NEAR(result->error, 5e-5, 1e-12);
  // A little farther inside, a cold solve may not converge, but it never ends farther from
  // the target than the straight chain would.
  Pose cold = rest_pose(chain);
  const Vec3 inside = chain.root_position() + Vec3(2.599, 0.0, 0.0);
  const auto near = solve_ik(GetParam(), chain, cold, inside);
  ASSERT_TRUE(near);
  EXPECT_LE(near->error, 1e-3 + 1e-12);
}

TEST_P(IkSolverTest, UnreachableTargetStraightensTheChainTowardIt) {
  const Vec3 target(3.0, 0.0, 2.0);  // 3.9 from the root, reach 2.6
  const auto result = solve_ik(GetParam(), chain, pose, target);
  ASSERT_TRUE(result);
  EXPECT_FALSE(result->reachable);
  EXPECT_FALSE(result->converged);
  const Vec3 root = chain.root_position();
  const Vec3 direction = (target - root).normalized();
  // End effector at full reach on the ray from the root to the target.
  EXPECT_LT((pose.end_effector() - (root + 2.6 * direction)).norm(), 1e-12);
  EXPECT_NEAR(result->error, (target - root).norm() - 2.6, 1e-12);
  // Every joint on that ray: the chain is straight and points at the target.
  for (int i = 1; i < chain.joint_count(); ++i) {
    const Vec3 along = pose.global_positions[i] - root;
    EXPECT_LT(along.cross(direction).norm(), 1e-12) << "joint " << i;
    EXPECT_GT(along.dot(direction), 0.0);
  }
  expect_bone_lengths_kept(pose);
}

TEST_P(IkSolverTest, TargetStraightBelowTheHangingArmIsReached) {
  // The lab's triangle starts at (0,0,0): on the line of the hanging arm, where every joint's
  // direction to the end effector and to the target agree. A singular pose to escape from.
  const auto result = solve_ik(GetParam(), chain, pose, Vec3(0.0, 0.0, 0.0));
  ASSERT_TRUE(result);
  EXPECT_TRUE(result->converged) << "error " << result->error;
  expect_bone_lengths_kept(pose);
}

TEST_P(IkSolverTest, TargetAlreadyReachedTakesNoIteration) {
  const auto result = solve_ik(GetParam(), chain, pose, Vec3(0.0, -0.9, 0.0));
  ASSERT_TRUE(result);
  EXPECT_EQ(result->iterations, 0);
  EXPECT_TRUE(result->converged);
}

TEST_P(IkSolverTest, SameInputSameBits) {
  Pose a = rest_pose(chain), b = rest_pose(chain);
  const auto targets = lab_shape_targets(LabShape::heart);
  for (const Vec3& t : targets) {
    const auto ra = solve_ik(GetParam(), chain, a, t);
    const auto rb = solve_ik(GetParam(), chain, b, t);
    ASSERT_TRUE(ra && rb);
    EXPECT_EQ(ra->iterations, rb->iterations);
    EXPECT_EQ(std::memcmp(&ra->error, &rb->error, sizeof(double)), 0);
  }
  for (int i = 0; i < chain.joint_count(); ++i) {
    EXPECT_EQ(std::memcmp(a.local_rotations[i].coeffs().data(),
                          b.local_rotations[i].coeffs().data(), 4 * sizeof(double)),
              0);
    EXPECT_EQ(
        std::memcmp(a.global_positions[i].data(), b.global_positions[i].data(), 3 * sizeof(double)),
        0);
  }
}

TEST_P(IkSolverTest, BadInputsGiveClearErrors) {
  EXPECT_EQ(error_for(Vec3(kNaN, 0, 0)), "target has a non-finite coordinate (nan, 0, 0)");
  EXPECT_EQ(error_for(Vec3(0, kInf, 0)), "target has a non-finite coordinate (0, inf, 0)");
  // Beyond what a solve can carry: 1e154 squared overflows, and used to bend the arm wrong.
  EXPECT_EQ(error_for(Vec3(1e154, 0, 0)),
            "target (1e+154, 0, 0) has a coordinate beyond +-1e+09, farther than a solve can "
            "place a chain");
  EXPECT_EQ(error_for(Vec3(0.3, 0, 0), IkOptions{.max_iterations = 0}),
            "max iterations must be at least 1, got 0");
  EXPECT_EQ(error_for(Vec3(0.3, 0, 0), IkOptions{.tolerance = 0.0}),
            "tolerance must be a positive finite number, got 0");
  EXPECT_EQ(error_for(Vec3(0.3, 0, 0), IkOptions{.tolerance = -1e-3}),
            "tolerance must be a positive finite number, got -0.001");
  EXPECT_EQ(error_for(Vec3(0.3, 0, 0), IkOptions{.tolerance = -1e-9}),
            "tolerance must be a positive finite number, got -1e-09");
  EXPECT_EQ(error_for(Vec3(0.3, 0, 0), IkOptions{.tolerance = kNaN}),
            "tolerance must be a positive finite number, got nan");
  Pose corrupted = pose;
  corrupted.local_rotations[2] = Quat(0.5, 0.0, 0.0, 0.0);
  std::swap(pose, corrupted);
  EXPECT_EQ(error_for(Vec3(0.3, 0, 0)), "pose joint 2 rotation is not a finite unit quaternion");
  pose = corrupted;
  pose.global_positions[4].x() = kNaN;
  EXPECT_EQ(error_for(Vec3(0.3, 0, 0)), "pose joint 4 has a non-finite position or rotation");
  pose.global_positions.pop_back();
  EXPECT_EQ(error_for(Vec3(0.3, 0, 0)), "pose has 4 joint positions but the chain has 5 joints");
}

TEST_P(IkSolverTest, ErrorsLeaveThePoseUntouched) {
  solve_ik(GetParam(), chain, pose, Vec3(0.4, 0.0, 0.1)).value();
  const Pose before = pose;
  EXPECT_FALSE(solve_ik(GetParam(), chain, pose, Vec3(kNaN, 0, 0)));
  for (int i = 0; i < chain.joint_count(); ++i) {
    EXPECT_EQ(pose.global_positions[i], before.global_positions[i]);
  }
}

INSTANTIATE_TEST_SUITE_P(BothSolvers, IkSolverTest,
                         testing::Values(IkSolverKind::ccd, IkSolverKind::fabrik),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

TEST(IkSolverNames, ParseAndPrint) {
  EXPECT_EQ(parse_ik_solver("ccd"), IkSolverKind::ccd);
  EXPECT_EQ(parse_ik_solver("fabrik"), IkSolverKind::fabrik);
  EXPECT_EQ(parse_ik_solver("FABRIK"), std::nullopt);
  EXPECT_EQ(all_ik_solvers().size(), 2u);
}

TEST(IkSolvers, FabrikNeedsFewerIterationsThanCcdOnTheStar) {
  // The lab's question 2, as a property: FABRIK converges in fewer iterations per target.
  const Chain chain = *build_chain(lab_arm());
  const auto star = lab_shape_targets(LabShape::star);
  DrawingOptions ccd, fabrik;
  ccd.solver = IkSolverKind::ccd;
  fabrik.solver = IkSolverKind::fabrik;
  const DrawingSummary c = summarize(*run_drawing(chain, star, ccd));
  const DrawingSummary f = summarize(*run_drawing(chain, star, fabrik));
  EXPECT_EQ(c.converged_fraction, 1.0);
  EXPECT_EQ(f.converged_fraction, 1.0);
  EXPECT_LT(f.iterations_mean, c.iterations_mean);
  EXPECT_LT(c.iterations_mean,
            20.0);  // double-precision CCD does not stall (the lab's float one does)
}

TEST(FabrikRotations, FromPreviousAvoidsTwistJumpsAndKeepsTheSolution) {
  // On the lab's triangle the arm folds bones past their rest direction's antipode, where the
  // shortest arc from rest swings its axis: measured 0.23 rad joint steps between frames.
  const Chain chain = *build_chain(lab_arm());
  const auto triangle = lab_shape_targets(LabShape::triangle);
  DrawingOptions rest, previous;
  rest.solver = previous.solver = IkSolverKind::fabrik;
  previous.ik.fabrik_rotations = FabrikRotations::from_previous;
  const auto a = run_drawing(chain, triangle, rest);
  const auto b = run_drawing(chain, triangle, previous);
  ASSERT_TRUE(a && b);
  for (std::size_t i = 0; i < triangle.size(); ++i) {
    // Positions are FABRIK's either way; only the rotations that reproduce them differ.
    EXPECT_LT((a->frames[i].end_effector - b->frames[i].end_effector).norm(), 1e-12);
    EXPECT_TRUE(b->frames[i].ik.converged);
  }
  const double step_rest = summarize(*a).max_joint_step_rad;
  const double step_previous = summarize(*b).max_joint_step_rad;
  EXPECT_LT(step_previous, 0.5 * step_rest);
  // Forward kinematics of the recovered rotations reproduces the positions.
  Pose replay = b->final_pose;
  forward_kinematics(chain, replay, 0);
  for (int i = 0; i < chain.joint_count(); ++i) {
    EXPECT_LT((replay.global_positions[i] - b->final_pose.global_positions[i]).norm(), 1e-12);
  }
}

TEST(Fabrik, RecoveredRotationsReproduceThePassPositions) {
  // The reaching passes find positions with every bone at its length; the rotations FABRIK
  // recovers from them must put forward kinematics back on those same positions.
  const Chain chain = *build_chain(lab_arm());
  for (FabrikRotations mode : {FabrikRotations::from_rest, FabrikRotations::from_previous}) {
    Pose passes = rest_pose(chain), solved = rest_pose(chain);
    for (const Vec3& target : lab_shape_targets(LabShape::heart)) {
      const IkOptions options{.fabrik_rotations = mode};
      const auto a = fabrik_reaching_passes(chain, passes, target, options);
      const auto b = solve_fabrik(chain, solved, target, options);
      ASSERT_TRUE(a && b);
      EXPECT_EQ(a->iterations, b->iterations);
      for (int i = 1; i < chain.joint_count(); ++i) {
        EXPECT_NEAR((passes.global_positions[i] - passes.global_positions[i - 1]).norm(),
                    chain.bone_lengths()[i], 1e-9);
        EXPECT_LT((solved.global_positions[i] - passes.global_positions[i]).norm(), 1e-12);
      }
      passes = solved;  // both continue from the consistent pose, as a drawing would
    }
  }
}

TEST(FabrikRotations, NamesRoundTrip) {
  EXPECT_EQ(parse_fabrik_rotations("rest"), FabrikRotations::from_rest);
  EXPECT_EQ(parse_fabrik_rotations("previous"), FabrikRotations::from_previous);
  EXPECT_EQ(parse_fabrik_rotations(to_string(FabrikRotations::from_previous)),
            FabrikRotations::from_previous);
  EXPECT_EQ(parse_fabrik_rotations("twist"), std::nullopt);
}

}  // namespace
}  // namespace animkit
