#include "animkit/kinematics/drawing_session.h"

#include <gtest/gtest.h>

#include <limits>

#include "animkit/trajectory/lab_shapes.h"

namespace animkit {
namespace {

class DrawingSession : public testing::Test {
 protected:
  Chain chain = *build_chain(lab_arm());
  std::vector<Vec3> circle = lab_shape_targets(LabShape::circle);
};

TEST_F(DrawingSession, OneFramePerTargetPerLap) {
  DrawingOptions options;
  options.laps = 3;
  const auto run = run_drawing(chain, circle, options);
  ASSERT_TRUE(run);
  ASSERT_EQ(run->frames.size(), 3 * circle.size());
  for (std::size_t i = 0; i < run->frames.size(); ++i) {
    EXPECT_EQ(run->frames[i].lap, static_cast<int>(i / circle.size()));
    EXPECT_EQ(run->frames[i].target, circle[i % circle.size()]);
    EXPECT_EQ(run->frames[i].joint_positions.size(), 5u);
    EXPECT_EQ(run->frames[i].joint_positions.back(), run->frames[i].end_effector);
  }
  EXPECT_EQ(run->final_pose.end_effector(), run->frames.back().end_effector);
}

TEST_F(DrawingSession, EveryLapStartsFromRestAsTheLabDoes) {
  DrawingOptions options;
  options.laps = 2;
  const auto run = run_drawing(chain, circle, options);
  ASSERT_TRUE(run);
  // Reset to rest at each lap's start: the laps are identical, bit for bit.
  for (std::size_t i = 0; i < circle.size(); ++i) {
    const DrawingFrame& a = run->frames[i];
    const DrawingFrame& b = run->frames[i + circle.size()];
    EXPECT_EQ(a.end_effector, b.end_effector);
    EXPECT_EQ(a.ik.iterations, b.ik.iterations);
    EXPECT_EQ(a.joint_step_rad, b.joint_step_rad);
  }
  EXPECT_EQ(run->frames[0].joint_step_rad, 0.0);
  EXPECT_EQ(run->frames[circle.size()].joint_step_rad, 0.0);
}

TEST_F(DrawingSession, WarmStartNeedsFewerIterationsThanColdStart) {
  DrawingOptions warm, cold;
  cold.warm_start = false;
  const DrawingSummary w = summarize(*run_drawing(chain, circle, warm));
  const DrawingSummary c = summarize(*run_drawing(chain, circle, cold));
  EXPECT_EQ(w.converged_fraction, 1.0);
  EXPECT_EQ(c.converged_fraction, 1.0);
  EXPECT_LT(w.iterations_mean, c.iterations_mean);
}

TEST_F(DrawingSession, JointStepIsTheLargestRotationChangeBetweenFrames) {
  const auto run = run_drawing(chain, circle);
  ASSERT_TRUE(run);
  const DrawingSummary s = summarize(*run);
  double largest = 0.0;
  for (const DrawingFrame& f : run->frames) {
    EXPECT_GE(f.joint_step_rad, 0.0);
    largest = std::max(largest, f.joint_step_rad);
  }
  EXPECT_EQ(s.max_joint_step_rad, largest);
  EXPECT_GT(largest, 0.0);
  // Neighbouring circle targets are 0.025 apart: a smooth drawing turns no joint by much.
  EXPECT_LT(largest, 0.1);
}

TEST_F(DrawingSession, SummaryCountsUnreachableTargets) {
  const std::vector<Vec3> targets{{0.3, 0.0, 0.0}, {5.0, 0.0, 0.0}, {0.2, 0.0, 0.1}};
  const auto run = run_drawing(chain, targets);
  ASSERT_TRUE(run);
  const DrawingSummary s = summarize(*run);
  EXPECT_EQ(s.targets, 3);
  EXPECT_EQ(s.unreachable_targets, 1);
  EXPECT_NEAR(s.converged_fraction, 2.0 / 3.0, 1e-15);
  EXPECT_FALSE(run->frames[1].ik.reachable);
}

TEST_F(DrawingSession, RejectsBadInput) {
  EXPECT_EQ(run_drawing(chain, {}).error().message, "the trajectory has no targets");
  std::vector<Vec3> targets = circle;
  targets[17].z() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(run_drawing(chain, targets).error().message.rfind("target 17 has a non-finite", 0), 0u);
  DrawingOptions options;
  options.laps = 0;
  EXPECT_EQ(run_drawing(chain, circle, options).error().message, "laps must be at least 1, got 0");
  options.laps = 1;
  options.ik.max_iterations = -5;
  EXPECT_EQ(run_drawing(chain, circle, options).error().message,
            "max iterations must be at least 1, got -5");
}

}  // namespace
}  // namespace animkit
