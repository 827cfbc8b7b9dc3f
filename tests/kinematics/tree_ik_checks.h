#pragma once
// Checks every tree IK solver must pass, written once over the shared signature (tree_ik.h):
// Solver is a struct with `using Settings`, `using Workspace` and a static `solve` that calls
// the solver. fabrik_tree_test.cpp and ccd_tree_test.cpp run them on their own solver.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "animkit/kinematics/ik_solver.h"
#include "../support/sanitizers.h"
#include "animkit/trajectory/lab_shapes.h"
#include "tree_ik_samples.h"

namespace animkit::tree_checks {

using tree_samples::body_limits;
using tree_samples::effectors_at;
using tree_samples::random_pose;

// Seeded random targets, a third of them beyond reach, on the figure's hands, feet and head
// (the head with an orientation target); after every solve the pose keeps its bones, its
// roots and every limit. `solves` in Release, a tenth of them under the sanitizers.
template <class Solver>
void limits_bones_and_roots_hold(int release_solves, std::uint64_t seed) {
  const int solves = test_support::trials_for_this_build(release_solves);
  const Skeleton s = tree_samples::figure();
  const std::vector<JointLimit> limits = body_limits(s);
  const auto joints = tree_samples::joints_named(s, {"l_hand", "r_hand", "l_foot", "r_foot"});
  const int head = s.find_joint("head");
  std::mt19937_64 rng(seed);
  typename Solver::Workspace workspace;
  SkeletonPose pose = skeleton_rest_pose(s);
  const SkeletonPose rest = pose;
  double worst = 0.0;
  int unreachable = 0;
  for (int k = 0; k < solves; ++k) {
    std::vector<Effector> effectors;
    for (int j : joints) {
      Vec3 target = Vec3(limit_samples::uniform(rng, -1, 1), limit_samples::uniform(rng, 0, 2),
                         limit_samples::uniform(rng, -1, 1));
      if (k % 3 == 0) target *= 4.0;  // beyond any reach
      effectors.push_back(Effector{j, target});
    }
    effectors.push_back(Effector{head, Vec3(0, 2, 0), limit_samples::random_rotation(rng), 0.5});
    if (k % 5 == 0) pose = rest;  // otherwise warm start from the previous solution
    const auto result = Solver::solve(s, TreeIkProblem{effectors, limits},
                                      typename Solver::Settings{}, workspace, pose);
    ASSERT_TRUE(result) << result.error().message;
    unreachable += !result->reachable;
    worst = std::max(worst, tree_samples::max_violation(s, limits, pose));
    tree_samples::expect_rigid(s, rest, pose);
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_LE(worst, 1e-9);
  EXPECT_GE(unreachable, solves / 3);  // the far targets were reported unreachable
}

// Targets made by FK of random poses inside the limits (so reachable together), solved from
// the rest pose; returns the fraction reached within the settings' tolerances.
template <class Solver>
double fraction_reached(const Skeleton& s, const std::vector<JointLimit>& limits,
                        const std::vector<int>& joints, bool with_orientation, int solves,
                        const typename Solver::Settings& settings, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  typename Solver::Workspace workspace;
  int reached = 0;
  for (int k = 0; k < solves; ++k) {
    const SkeletonPose goal = random_pose(s, limits, rng, 1.2);
    const std::vector<Effector> effectors = effectors_at(goal, joints, with_orientation);
    SkeletonPose pose = skeleton_rest_pose(s);
    const auto result =
        Solver::solve(s, TreeIkProblem{effectors, limits}, settings, workspace, pose);
    EXPECT_TRUE(result);
    if (!result) return 0.0;
    EXPECT_TRUE(result->reachable);
    EXPECT_LE(tree_samples::max_violation(s, limits, pose), 1e-9);
    const TreeIkErrors errors = tree_ik_errors(pose, effectors);
    EXPECT_EQ(result->error, errors.position);
    const bool ok =
        errors.position <= settings.tolerance && errors.orientation <= settings.angular_tolerance;
    EXPECT_EQ(result->converged, ok);
    reached += ok;
  }
  return static_cast<double>(reached) / solves;
}

// Invalid problems and settings fail with the message validate_tree_ik (or the settings'
// validate) gives, and leave the pose alone.
template <class Solver>
void invalid_input_fails_with_its_message() {
  const Skeleton s = tree_samples::figure();
  SkeletonPose pose = skeleton_rest_pose(s);
  const SkeletonPose before = pose;
  typename Solver::Workspace workspace;
  const std::vector<Effector> on_root{Effector{0, Vec3(0, 0, 0)}};
  const TreeIkProblem bad{on_root};
  auto result = Solver::solve(s, bad, typename Solver::Settings{}, workspace, pose);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message, validate_tree_ik(s, bad, pose)->message);
  EXPECT_EQ(result.error().message, "effector 0 is on the root hips, which IK never moves");

  const std::vector<Effector> ok{Effector{s.find_joint("l_hand"), Vec3(1, 1, 0)}};
  const std::vector<JointLimit> too_few(3, FreeJoint{});
  result =
      Solver::solve(s, TreeIkProblem{ok, too_few}, typename Solver::Settings{}, workspace, pose);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message, "joint limits: 3 given, the skeleton has 16 joints");

  typename Solver::Settings settings;
  settings.tolerance = -1.0;
  result = Solver::solve(s, TreeIkProblem{ok}, settings, workspace, pose);
  ASSERT_FALSE(result);
  EXPECT_EQ(result.error().message, "tolerance must be a positive finite number, got -1");
  EXPECT_EQ(settings.validate()->message, result.error().message);
  settings = {};
  settings.max_iterations = 0;
  EXPECT_EQ(settings.validate()->message, "max iterations must be at least 1, got 0");
  settings = {};
  settings.angular_tolerance = 0.0;
  EXPECT_EQ(settings.validate()->message,
            "angular tolerance must be a positive finite number, got 0");
  EXPECT_FALSE(typename Solver::Settings{}.validate());
  EXPECT_TRUE(tree_samples::same_bits(pose, before));
}

// Same input, same bits; one workspace reused over many solves (and first sized for another
// skeleton) gives the bits a fresh workspace gives.
template <class Solver>
void deterministic_and_workspace_reuse_is_invisible(std::uint64_t seed) {
  const Skeleton s = tree_samples::figure();
  const std::vector<JointLimit> limits = body_limits(s);
  const auto joints = tree_samples::joints_named(s, {"l_hand", "r_hand", "l_foot", "head"});
  std::mt19937_64 rng(seed);
  typename Solver::Workspace reused;
  reused.resize(build_skeleton(skeleton_desc_from_chain(lab_arm())).value());
  for (int k = 0; k < 50; ++k) {
    const SkeletonPose goal = random_pose(s, limits, rng, 1.5);
    const std::vector<Effector> effectors = effectors_at(goal, joints, k % 2 == 0);
    const SkeletonPose start = random_pose(s, limits, rng, 0.5);
    const TreeIkProblem problem{effectors, limits};
    SkeletonPose a = start, b = start, c = start;
    typename Solver::Workspace fresh_b, fresh_c;
    const auto ra = Solver::solve(s, problem, typename Solver::Settings{}, reused, a);
    const auto rb = Solver::solve(s, problem, typename Solver::Settings{}, fresh_b, b);
    const auto rc = Solver::solve(s, problem, typename Solver::Settings{}, fresh_c, c);
    ASSERT_TRUE(ra && rb && rc);
    EXPECT_TRUE(tree_samples::same_bits(a, b)) << k;
    EXPECT_TRUE(tree_samples::same_bits(b, c)) << k;
    EXPECT_EQ(ra->iterations, rb->iterations);
    EXPECT_EQ(ra->error, rb->error);
    EXPECT_EQ(ra->orientation_error, rb->orientation_error);
  }
}

// Fractions of jointly reachable targets reached (fraction_reached) in five set-ups.
struct ReachFractions {
  double free_default = 0.0;  ///< no limits, the default settings (100 iterations)
  double free = 0.0;          ///< no limits, 1000 iterations
  double oriented = 0.0;      ///< no limits, orientation targets too, 1000 iterations
  double balls = 0.0;         ///< ball limits only, 1000 iterations
  double hinges = 0.0;        ///< balls and hinged knees and elbows, 1000 iterations
};

// The lab's arm as a one-branch skeleton reaches what the chain's solver `chain_solver`
// reaches: every 7th point of the lab's shapes, one target per frame, warm-started from the
// previous frame as the lab drives it.
template <class Solver>
void lab_arm_reaches_the_chain_solvers_targets(IkSolverKind chain_solver) {
  const Chain chain = build_chain(lab_arm()).value();
  const Skeleton s = build_skeleton(skeleton_desc_from_chain(lab_arm())).value();
  const int end = s.joint_count() - 1;
  typename Solver::Workspace workspace;
  int targets = 0;
  for (const LabShape shape : all_lab_shapes()) {
    Pose chain_pose = rest_pose(chain);
    SkeletonPose pose = skeleton_rest_pose(s);
    const std::vector<Vec3> points = lab_shape_targets(shape);
    for (std::size_t k = 0; k < points.size(); k += 7) {
      const auto chain_result = solve_ik(chain_solver, chain, chain_pose, points[k]);
      ASSERT_TRUE(chain_result);
      if (!chain_result->converged) continue;
      const std::vector<Effector> effectors{Effector{end, points[k]}};
      const auto result =
          Solver::solve(s, TreeIkProblem{effectors}, typename Solver::Settings{}, workspace, pose);
      ASSERT_TRUE(result) << result.error().message;
      EXPECT_TRUE(result->converged) << to_string(shape) << " point " << k;
      EXPECT_LE((pose.global_positions[static_cast<std::size_t>(end)] - points[k]).norm(), 1e-4);
      ++targets;
    }
  }
  EXPECT_GT(targets, 100);
}

template <class Solver>
ReachFractions reach_fractions(const Skeleton& s, const std::vector<int>& joints, int solves) {
  typename Solver::Settings settings;
  ReachFractions f;
  f.free_default = fraction_reached<Solver>(s, {}, joints, false, solves, settings, 3);
  settings.max_iterations = 1000;
  f.free = fraction_reached<Solver>(s, {}, joints, false, solves, settings, 4);
  f.oriented = fraction_reached<Solver>(s, {}, joints, true, solves, settings, 5);
  f.balls = fraction_reached<Solver>(s, body_limits(s, false), joints, false, solves, settings, 6);
  f.hinges = fraction_reached<Solver>(s, body_limits(s, true), joints, false, solves, settings, 7);
  return f;
}

inline std::string describe(const ReachFractions& f) {
  return "free (100 iterations) " + std::to_string(f.free_default) + ", free " +
         std::to_string(f.free) + ", oriented " + std::to_string(f.oriented) + ", balls " +
         std::to_string(f.balls) + ", hinges " + std::to_string(f.hinges);
}

}  // namespace animkit::tree_checks
