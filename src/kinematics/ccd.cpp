#include "animkit/kinematics/ccd.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "animkit/core/quaternion_math.h"
#include "animkit/kinematics/forward_kinematics.h"
#include "ik_common.h"

namespace animkit {

namespace {

// One CCD sweep, end to root: arcs[i] is the world rotation that turns (joint i -> end
// effector) onto (joint i -> target). Turning joint i moves only joints i+1..end, and the
// joints still to visit (i-1..0) read nothing of those but the end effector, so the sweep
// carries the end effector along instead of re-running forward kinematics after every
// joint. The rotations are the same as re-running FK after each joint.
void sweep_arcs(const Pose& pose, const Vec3& target, std::vector<Quat>& arcs) {
  const auto& p = pose.global_positions;
  const int end = static_cast<int>(p.size()) - 1;
  Vec3 end_effector = p[end];
  for (int i = end - 1; i >= 0; --i) {
    const Vec3 to_end = end_effector - p[i];
    const Vec3 to_target = target - p[i];
    const double to_end2 = to_end.squaredNorm(), to_target2 = to_target.squaredNorm();
    // A joint sitting on the end effector or on the target has no direction to turn.
    if (to_end2 == 0.0 || to_target2 == 0.0) {
      arcs[i] = Quat::Identity();
      continue;
    }
    arcs[i] = shortest_arc(to_end, to_target);
    // The arc turns (joint -> end) onto the direction of (joint -> target), length kept:
    // computed from the directions, it keeps the arc off the chain of dependent operations.
    end_effector = p[i] + to_target * std::sqrt(to_end2 / to_target2);
  }
}

// Applies world rotations arcs[0..end-1], each about its joint's position at the start of the
// sweep, to the whole pose. The arc at joint i turns every bone from i on, so bone k turns by
// arcs[0] * ... * arcs[k] (the later-visited joints' arcs act last, hence on the left).
void apply_sweep(Pose& pose, const std::vector<Quat>& arcs) {
  auto& p = pose.global_positions;
  auto& g = pose.global_rotations;
  const std::size_t end = p.size() - 1;
  Quat turn = Quat::Identity();
  Vec3 old_start = p[0];
  for (std::size_t k = 0; k < end; ++k) {
    turn = turn * arcs[k];
    g[k] = turn * g[k];
    const Vec3 bone = p[k + 1] - old_start;
    old_start = p[k + 1];
    p[k + 1] = p[k] + turn * bone;
  }
  g[end] = turn * g[end];
}

}  // namespace

Result<IkResult> solve_ccd(const Chain& chain, Pose& pose, const Vec3& target,
                           const IkOptions& options) {
  if (auto settled = detail::settle_without_iterating(chain, pose, target, options)) {
    return *settled;
  }

  const int end = chain.joint_count() - 1;
  const Quat end_rotation = pose.local_rotations[end];  // the end joint never turns
  IkResult result;
  result.reachable = detail::within_reach(chain, target);
  // Squared distances in the loop: a square root less on each sweep's critical path.
  const double tolerance2 = options.tolerance * options.tolerance;
  constexpr double kStall2 = (1.0 - detail::kStallRatio) * (1.0 - detail::kStallRatio);
  auto& p = pose.global_positions;
  // During the sweeps the world rotations and positions are the state; local_rotations holds
  // each sweep's per-joint arcs and gets its real values back when the solve ends.
  auto& arcs = pose.local_rotations;
  double error2 = (p[end] - target).squaredNorm();
  if (error2 <= tolerance2) {
    result.error = std::sqrt(error2);
    result.converged = true;
    return result;
  }
  while (error2 > tolerance2 && result.iterations < options.max_iterations) {
    sweep_arcs(pose, target, arcs);
    apply_sweep(pose, arcs);
    ++result.iterations;
    const double previous_error2 = error2;
    error2 = (p[end] - target).squaredNorm();
    if (error2 > tolerance2 && error2 >= previous_error2 * kStall2) {
      if (!detail::on_singular_line(chain, p, target)) break;  // rounding level: stop
      // Singular pose (see kStallRatio): swing the chain about the root off the line (a kick
      // at the last joints would be undone by the next sweep) and go on.
      std::fill(arcs.begin(), arcs.end(), Quat::Identity());
      arcs[0] = detail::stall_kick(chain, pose, target);
      apply_sweep(pose, arcs);
      error2 = (p[end] - target).squaredNorm();
    }
  }
  // Local rotations back from the world ones; FK then makes the pose exactly consistent.
  arcs[0] = pose.global_rotations[0].normalized();
  for (int i = 1; i < end; ++i) {
    arcs[i] = (pose.global_rotations[i - 1].conjugate() * pose.global_rotations[i]).normalized();
  }
  arcs[end] = end_rotation;
  forward_kinematics(chain, pose, 0);
  result.error = (p[end] - target).norm();
  result.converged = result.error <= options.tolerance;
  detail::prefer_straight_if_nearer(chain, pose, target, options, result);
  return result;
}

}  // namespace animkit
