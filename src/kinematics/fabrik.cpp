#include "animkit/kinematics/fabrik.h"

#include <cmath>

#include "animkit/core/quaternion_math.h"
#include "animkit/kinematics/forward_kinematics.h"
#include "ik_common.h"

namespace animkit {

namespace {

// Moves `joint` onto the sphere of radius `length` around `anchor`, along the line joining
// them (the "reaching" step of FABRIK). When the two coincide the line is undefined and the
// bone takes its direction from the pose the solve started with (`rest_bone` turned by
// `rotation`, negated for the backward pass); computed only then, as it is rarely needed.
void reach_toward(const Vec3& anchor, Vec3& joint, double length, const Quat& rotation,
                  const Vec3& rest_bone, double sign) {
  const Vec3 d = joint - anchor;
  const double norm2 = d.squaredNorm();
  joint = norm2 > 0.0 ? Vec3(anchor + d * (length / std::sqrt(norm2)))
                      : Vec3(anchor + (sign * length) * (rotation * rest_bone).normalized());
}

// FABRIK, Aristidou & Lasenby 2011, Alg. 1 (reachable branch), in place on the positions:
// the backward pass pins the end joint on the target and walks to the root; the forward pass
// pins the root back and walks out again. Each pass keeps every bone at its length.
void backward_forward_pass(const Chain& chain, Pose& pose, const Vec3& target) {
  auto& p = pose.global_positions;
  const auto& g = pose.global_rotations;
  const int end = chain.joint_count() - 1;
  p[end] = target;
  // The backward pass stops at joint 1: joint 0 would be moved only to be put back on the
  // root by the forward pass, which reads nothing of it.
  for (int i = end - 1; i >= 1; --i) {
    reach_toward(p[i + 1], p[i], chain.bone_lengths()[i + 1], g[i], chain.local_offsets()[i + 1],
                 -1.0);
  }
  p[0] = chain.root_position();
  for (int i = 0; i < end; ++i) {
    reach_toward(p[i], p[i + 1], chain.bone_lengths()[i + 1], g[i], chain.local_offsets()[i + 1],
                 1.0);
  }
}

// Rotations from positions (see FabrikRotations); local = parent^-1 * global. The end joint
// keeps its local rotation. Forward kinematics then makes the pose exactly consistent.
void recover_rotations(const Chain& chain, Pose& pose, FabrikRotations mode) {
  const auto& p = pose.global_positions;
  Quat parent = Quat::Identity();
  for (int i = 0; i + 1 < chain.joint_count(); ++i) {
    const Vec3 bone = p[i + 1] - p[i];
    Quat global;
    if (mode == FabrikRotations::from_rest) {
      global = shortest_arc(chain.local_offsets()[i + 1], bone);
    } else {
      // global_rotations still hold the pose the solve started from.
      const Quat& before = pose.global_rotations[i];
      global = (shortest_arc(before * chain.local_offsets()[i + 1], bone) * before).normalized();
    }
    // A product of unit quaternions, rebuilt from fresh arcs at every solve: no drift to undo.
    pose.local_rotations[i] = parent.conjugate() * global;
    parent = global;
  }
  forward_kinematics(chain, pose, 0);
}

}  // namespace

Result<IkResult> fabrik_reaching_passes(const Chain& chain, Pose& pose, const Vec3& target,
                                        const IkOptions& options) {
  if (auto settled = detail::settle_without_iterating(chain, pose, target, options)) {
    return *settled;
  }

  IkResult result;
  result.reachable = detail::within_reach(chain, target);
  // Squared distances in the loop: a square root less on each pass's critical path.
  const double tolerance2 = options.tolerance * options.tolerance;
  constexpr double kStall2 = (1.0 - detail::kStallRatio) * (1.0 - detail::kStallRatio);
  double error2 = (pose.end_effector() - target).squaredNorm();
  while (error2 > tolerance2 && result.iterations < options.max_iterations) {
    backward_forward_pass(chain, pose, target);
    ++result.iterations;
    const double previous_error2 = error2;
    error2 = (pose.end_effector() - target).squaredNorm();
    auto& p = pose.global_positions;
    if (error2 > tolerance2 && error2 >= previous_error2 * kStall2) {
      if (!detail::on_singular_line(chain, p, target)) break;  // rounding level: stop
      // Singular pose (see kStallRatio): swing the chain about the root off the line, so the
      // next backward pass bends it, and go on.
      const Quat kick = detail::stall_kick(chain, pose, target);
      for (std::size_t k = 1; k < p.size(); ++k) p[k] = p[0] + kick * (p[k] - p[0]);
      error2 = (pose.end_effector() - target).squaredNorm();
    }
  }
  result.error = std::sqrt(error2);
  result.converged = result.error <= options.tolerance;
  return result;
}

Result<IkResult> solve_fabrik(const Chain& chain, Pose& pose, const Vec3& target,
                              const IkOptions& options) {
  auto result = fabrik_reaching_passes(chain, pose, target, options);
  if (!result || result->iterations == 0) return result;  // error, or nothing moved
  recover_rotations(chain, pose, options.fabrik_rotations);
  result->error = (pose.end_effector() - target).norm();
  result->converged = result->error <= options.tolerance;
  detail::prefer_straight_if_nearer(chain, pose, target, options, *result);
  return result;
}

}  // namespace animkit
