#include "animkit/kinematics/hand_reach.h"

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "animkit/core/validation.h"
#include "animkit/kinematics/tree_ik_solver.h"

namespace animkit {

namespace {

// The skeleton with each root's rest rotation set to its rotation in `pose`: a limit with no
// range then holds the root exactly as the pose has it, since limits are taken relative to the
// rest rotation (tree_ik.h). The other joints' rest rotations, and so their limits, are kept.
Result<Skeleton> with_roots_at(const Skeleton& skeleton, const SkeletonPose& pose) {
  SkeletonDesc desc;
  desc.names = skeleton.names();
  desc.parents = skeleton.parents();
  desc.rest_offsets = skeleton.rest_offsets();
  desc.rest_rotations = skeleton.rest_rotations();
  for (int root : skeleton.roots()) {
    desc.rest_rotations[static_cast<std::size_t>(root)] =
        pose.local_rotations[static_cast<std::size_t>(root)];
  }
  return build_skeleton(desc);
}

}  // namespace

std::optional<Error> HandReachSettings::validate() const {
  FabrikTreeSettings stopping;  // every solver checks these two with the same words
  stopping.max_iterations = max_iterations;
  stopping.tolerance = tolerance;
  if (auto error = stopping.validate()) return error;
  if (!(foot_weight > 0.0 && foot_weight < 1e300)) {
    return Error{"foot weight must be a positive finite number, got " + format_number(foot_weight)};
  }
  return std::nullopt;
}

Result<HandReachResult> reach_hand(const Skeleton& skeleton, std::span<const JointLimit> limits,
                                   int hand, std::array<int, 2> feet, const Vec3& target,
                                   const HandReachSettings& settings, SkeletonPose& pose) {
  if (auto error = settings.validate()) return fail(error->message);
  if (!is_finite(target)) return fail("the hand's target " + to_string(target) + " is not finite");
  const int n = skeleton.joint_count();
  if (!limits.empty() && static_cast<int>(limits.size()) != n) {
    return fail("joint limits: " + std::to_string(limits.size()) + " given, the skeleton has " +
                std::to_string(n) + " joints");
  }
  // The pose's sizes and the three joints first, in validate_tree_ik's words: everything below
  // indexes the pose by them.
  const std::array<Effector, 3> probe{Effector{hand, target}, Effector{feet[0], target},
                                      Effector{feet[1], target}};
  if (auto error = validate_tree_ik(skeleton, TreeIkProblem{probe, {}}, pose)) {
    return fail(error->message);
  }
  for (int root : skeleton.roots()) {
    const Quat& q = pose.local_rotations[static_cast<std::size_t>(root)];
    if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-9) {
      return fail("the pose's rotation of root joint " +
                  skeleton.names()[static_cast<std::size_t>(root)] + " is not a unit quaternion");
    }
  }
  const auto held = with_roots_at(skeleton, pose);
  if (!held) return fail(held.error().message);

  // Only joints between the root and an effector may turn; the others (the other arm, the
  // head) follow their parent rigidly. Their limits are dropped, so a clip pose that breaks
  // them is kept instead of being pulled inside (which would move a joint that plays no part).
  std::vector<JointLimit> bounded(static_cast<std::size_t>(n), FreeJoint{});
  if (!limits.empty()) {
    for (int effector : {hand, feet[0], feet[1]}) {
      for (int j = effector; j >= 0 && j < n; j = skeleton.parents()[static_cast<std::size_t>(j)]) {
        bounded[static_cast<std::size_t>(j)] = limits[static_cast<std::size_t>(j)];
      }
    }
  }
  for (int root : skeleton.roots()) {
    // The twist axis is any unit axis: with no swing and no twist nothing turns.
    bounded[static_cast<std::size_t>(root)] = BallLimit{Vec3::UnitY(), 0.0, 0.0, 0.0};
  }
  auto at = [&](int joint) -> Vec3 {
    return joint >= 0 && joint < n ? pose.global_positions[static_cast<std::size_t>(joint)]
                                   : Vec3::Zero();
  };
  const std::array<Vec3, 2> feet_before{at(feet[0]), at(feet[1])};
  const int root = skeleton.roots().front();
  const Vec3 root_before = at(root);
  const std::array<Effector, 3> effectors{
      Effector{hand, target}, Effector{feet[0], feet_before[0], std::nullopt, settings.foot_weight},
      Effector{feet[1], feet_before[1], std::nullopt, settings.foot_weight}};

  TreeIkSolvers solvers;
  solvers.set_stopping(settings.max_iterations, settings.tolerance);
  const auto start = std::chrono::steady_clock::now();
  const auto solved =
      solve_tree_ik(settings.solver, *held, TreeIkProblem{effectors, bounded}, solvers, pose);
  const auto stop = std::chrono::steady_clock::now();
  if (!solved) return fail(solved.error().message);

  HandReachResult result;
  result.ik = *solved;
  result.hand_error = (at(hand) - target).norm();
  result.foot_drift =
      std::max((at(feet[0]) - feet_before[0]).norm(), (at(feet[1]) - feet_before[1]).norm());
  result.root_drift = (at(root) - root_before).norm();
  result.reached =
      result.hand_error <= settings.tolerance && result.foot_drift <= settings.tolerance;
  result.solve_ms = std::chrono::duration<double, std::milli>(stop - start).count();
  return result;
}

}  // namespace animkit
