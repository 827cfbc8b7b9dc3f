// The lab's drawing session on a skeleton (skeleton_drawing_session.h): without limits it draws
// what the chain session draws; with limits every frame stays inside them; bad input is refused
// with the chain session's words.
#include "animkit/kinematics/skeleton_drawing_session.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "animkit/core/quaternion_math.h"
#include "animkit/trajectory/lab_shapes.h"

namespace animkit {
namespace {

Skeleton lab_skeleton() {
  return build_skeleton(skeleton_desc_from_chain(lab_arm())).value();
}

TEST(SkeletonDrawingSession, CcdWithoutLimitsDrawsTheChainSessionsPath) {
  const Chain chain = build_chain(lab_arm()).value();
  const Skeleton skeleton = lab_skeleton();
  for (const LabShape shape : all_lab_shapes()) {
    const std::vector<Vec3> targets = lab_shape_targets(shape);
    const auto lab = run_drawing(chain, targets);
    const auto tree = run_skeleton_drawing(skeleton, 4, {}, targets);
    ASSERT_TRUE(lab && tree);
    ASSERT_EQ(lab->frames.size(), tree->frames.size());
    // The star is drawn to 1e-9 with the same iterations. On the other shapes the two
    // sessions, warm-started frame after frame, part by rounding somewhere and then follow
    // nearby poses: both ends still within the tolerance of each target.
    const bool exact = shape == LabShape::star;
    for (std::size_t f = 0; f < lab->frames.size(); ++f) {
      const DrawingFrame& a = lab->frames[f];
      const DrawingFrame& b = tree->frames[f];
      EXPECT_LT((a.end_effector - b.end_effector).norm(), exact ? 1e-9 : 2e-4)
          << to_string(shape) << " " << f;
      if (exact) {
        EXPECT_EQ(a.ik.iterations, b.ik.iterations) << f;
      }
      EXPECT_EQ(a.ik.converged, b.ik.converged);
      EXPECT_EQ(a.ik.reachable, b.ik.reachable);
      ASSERT_EQ(b.joint_positions.size(), 5u);
    }
    const DrawingSummary sa = summarize(*lab), sb = summarize(*tree);
    EXPECT_EQ(sa.converged_fraction, sb.converged_fraction);
    EXPECT_EQ(sa.unreachable_targets, sb.unreachable_targets);
    EXPECT_NEAR(sa.max_joint_step_rad, sb.max_joint_step_rad, exact ? 1e-9 : 1e-3);
  }
}

// Hinge and ball limits on the lab's arm: every solver keeps every frame's pose inside them
// (checked on the final pose, which each frame starts from, and on the recorded positions: the
// planar hinges below keep the arm in z = 0).
TEST(SkeletonDrawingSession, LimitsHoldOnEveryFrameForEverySolver) {
  const Skeleton skeleton = lab_skeleton();
  std::vector<JointLimit> planar(5, HingeLimit{Vec3::UnitZ(), -2.5, 2.5});
  const std::vector<Vec3> targets = lab_shape_targets(LabShape::star);
  for (const TreeIkSolverKind solver : all_tree_ik_solvers()) {
    SkeletonDrawingOptions options;
    options.solver = solver;
    const auto run = run_skeleton_drawing(skeleton, 4, planar, targets, options);
    ASSERT_TRUE(run) << run.error().message;
    double largest_z = 0.0;
    for (const DrawingFrame& f : run->frames) {
      for (const Vec3& p : f.joint_positions) largest_z = std::max(largest_z, std::abs(p.z()));
      EXPECT_LE(f.ik.iterations, options.max_iterations);
    }
    EXPECT_LT(largest_z, 1e-9) << to_string(solver);
    for (int j = 0; j < 5; ++j) {
      EXPECT_LE(violation(planar[j], run->final_pose.local_rotations[j]), 1e-9) << j;
    }
    // Star targets lie off the plane: the planar arm misses most of them.
    EXPECT_LT(summarize(*run).converged_fraction, 0.5) << to_string(solver);
  }
}

TEST(SkeletonDrawingSession, BadInputIsRefusedWithTheChainSessionsWords) {
  const Skeleton skeleton = lab_skeleton();
  const std::vector<Vec3> targets{Vec3(0.3, 0, 0), Vec3(NAN, 0, 0)};
  auto run = run_skeleton_drawing(skeleton, 4, {}, targets);
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error().message, "target 1 has a non-finite coordinate (nan, 0, 0)");
  run = run_skeleton_drawing(skeleton, 4, {}, std::span<const Vec3>{});
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error().message, "the trajectory has no targets");
  SkeletonDrawingOptions options;
  options.laps = 0;
  run = run_skeleton_drawing(skeleton, 4, {}, std::span(targets).first(1), options);
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error().message, "laps must be at least 1, got 0");
  options = {};
  options.tolerance = -1;
  EXPECT_EQ(options.validate()->message, "tolerance must be a positive finite number, got -1");
  run = run_skeleton_drawing(skeleton, 0, {}, std::span(targets).first(1));
  ASSERT_FALSE(run);
  EXPECT_NE(run.error().message.find("root"), std::string::npos) << run.error().message;
  const std::vector<JointLimit> too_few(2, FreeJoint{});
  run = run_skeleton_drawing(skeleton, 4, too_few, std::span(targets).first(1));
  ASSERT_FALSE(run);
  EXPECT_EQ(run.error().message, "joint limits: 2 given, the skeleton has 5 joints");
}

}  // namespace
}  // namespace animkit
