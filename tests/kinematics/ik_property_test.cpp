// Property test: random valid chains and targets through every IK solver, checking what must
// hold for any input: finite results, bone lengths kept, unit rotations, honest convergence
// and reachability flags.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "animkit/core/validation.h"
#include "animkit/kinematics/ik_solver.h"

namespace animkit {
namespace {

Vec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Vec3 v;
  do {
    v = Vec3(normal(rng), normal(rng), normal(rng));
  } while (v.norm() < 1e-6);
  return v.normalized();
}

class IkProperty : public testing::TestWithParam<IkSolverKind> {};

TEST_P(IkProperty, RandomChainsAndTargetsKeepEveryInvariant) {
  std::mt19937 rng(20261123);
  std::uniform_int_distribution<int> joints(2, 9);
  std::uniform_real_distribution<double> length(0.05, 2.0), unit(0.0, 1.0);
  int solves = 0, converged = 0;
  for (int chain_number = 0; chain_number < 200; ++chain_number) {
    ChainDesc desc;
    desc.local_offsets.push_back(Vec3(unit(rng), unit(rng), unit(rng)) * 4.0 - Vec3::Constant(2.0));
    const int n = joints(rng);
    for (int i = 1; i < n; ++i) desc.local_offsets.push_back(length(rng) * random_direction(rng));
    const auto chain = build_chain(desc);
    ASSERT_TRUE(chain) << chain.error().message;
    Pose pose = rest_pose(*chain);
    for (int t = 0; t < 20; ++t) {  // warm-started, like a drawing
      // Targets from the root out to twice the reach: reachable, unreachable and in between.
      const Vec3 target =
          chain->root_position() + 2.0 * unit(rng) * chain->reach() * random_direction(rng);
      const auto result = solve_ik(GetParam(), *chain, pose, target);
      ASSERT_TRUE(result) << result.error().message;
      ++solves;
      converged += result->converged ? 1 : 0;
      ASSERT_TRUE(std::isfinite(result->error));
      EXPECT_NEAR(result->error, (pose.end_effector() - target).norm(), 1e-9);
      EXPECT_EQ(result->converged, result->error <= IkOptions{}.tolerance);
      const double distance = (target - chain->root_position()).norm();
      if (distance > chain->reach() + 1e-9) {
        EXPECT_FALSE(result->reachable);
        // Beyond reach the chain points straight at the target: the nearest it can get.
        EXPECT_NEAR(result->error, distance - chain->reach(), 1e-9);
      }
      for (int i = 0; i < chain->joint_count(); ++i) {
        ASSERT_TRUE(is_finite(pose.global_positions[i]));
        EXPECT_NEAR(pose.local_rotations[i].norm(), 1.0, 1e-12);
        if (i > 0) {
          EXPECT_NEAR((pose.global_positions[i] - pose.global_positions[i - 1]).norm(),
                      chain->bone_lengths()[i], 1e-9);
        }
      }
    }
  }
  // Most random targets are reachable and solved; the flags above say which are not.
  EXPECT_GT(converged, solves / 3);
}

INSTANTIATE_TEST_SUITE_P(Solvers, IkProperty, testing::ValuesIn(all_ik_solvers()),
                         [](const auto& param_info) {
                           return std::string(to_string(param_info.param));
                         });

}  // namespace
}  // namespace animkit
