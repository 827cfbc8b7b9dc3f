#include "animkit/kinematics/ccd.h"

#include <cmath>

#include "animkit/core/quaternion_math.h"
#include "animkit/kinematics/forward_kinematics.h"
#include "ik_common.h"

namespace animkit {

Result<IkResult> solve_ccd(const Chain& chain, Pose& pose, const Vec3& target,
                           const IkOptions& options) {
  if (auto error = detail::validate_ik_input(chain, pose, target, options)) {
    return fail(error->message);
  }
  const double distance = (target - chain.root_position()).norm();
  if (distance > chain.reach) return detail::point_chain_at(chain, pose, target, options);

  const int end = chain.joint_count() - 1;
  IkResult result;
  result.reachable = distance >= chain.min_reach;
  // Squared distances in the loop: a square root less on each sweep's critical path.
  const double tolerance2 = options.tolerance * options.tolerance;
  constexpr double kStall2 = (1.0 - detail::kStallRatio) * (1.0 - detail::kStallRatio);
  auto& p = pose.global_positions;
  double error2 = (p[end] - target).squaredNorm();
  while (error2 > tolerance2 && result.iterations < options.max_iterations) {
    // One sweep, end to root. Turning joint i by the world rotation `arc` moves only joints
    // i+1..end, and the joints still to visit (i-1..0) read nothing of those but the end
    // effector. So instead of re-running forward kinematics after every joint, the sweep
    // carries the end effector along and sets joint i's new local rotation
    // parent^-1 * arc * global[i] from the globals of the sweep's start, which the joints
    // visited so far have not changed. Same rotations as re-running FK after each joint; FK
    // runs once per sweep.
    Vec3 end_effector = p[end];
    for (int i = end - 1; i >= 0; --i) {
      const Vec3 to_end = end_effector - p[i];
      const Vec3 to_target = target - p[i];
      const double to_end2 = to_end.squaredNorm(), to_target2 = to_target.squaredNorm();
      // A joint sitting on the end effector or on the target has no direction to turn.
      if (to_end2 == 0.0 || to_target2 == 0.0) continue;
      const Quat global = shortest_arc(to_end, to_target) * pose.global_rotations[i];
      pose.local_rotations[i] =
          i == 0 ? global.normalized()
                 : (pose.global_rotations[i - 1].conjugate() * global).normalized();
      // The arc turns (joint -> end) onto the direction of (joint -> target), length kept.
      // Computed from the directions rather than by rotating: it keeps the arc's arithmetic
      // off the chain of dependent operations from one joint to the next.
      end_effector = p[i] + to_target * std::sqrt(to_end2 / to_target2);
    }
    forward_kinematics(chain, pose, 0);
    ++result.iterations;
    const double previous_error2 = error2;
    error2 = (p[end] - target).squaredNorm();
    if (error2 > tolerance2 && error2 >= previous_error2 * kStall2) {
      // Singular pose (see kStallRatio): swing the chain about the root off the line (a kick
      // at the last joints would be undone by the next sweep) and go on.
      pose.local_rotations[0] =
          (detail::stall_kick(chain, pose, target) * pose.local_rotations[0]).normalized();
      forward_kinematics(chain, pose, 0);
      error2 = (p[end] - target).squaredNorm();
    }
  }
  result.error = std::sqrt(error2);
  result.converged = result.error <= options.tolerance;
  return result;
}

}  // namespace animkit
