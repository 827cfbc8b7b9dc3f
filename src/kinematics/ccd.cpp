#include "animkit/kinematics/ccd.h"

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

  forward_kinematics(chain, pose, 0);
  const int n = chain.joint_count();
  const int end = n - 1;
  IkResult result;
  result.reachable = distance >= chain.min_reach;
  result.error = (pose.global_positions[end] - target).norm();
  while (result.error > options.tolerance && result.iterations < options.max_iterations) {
    for (int i = end - 1; i >= 0; --i) {
      const Vec3& joint = pose.global_positions[i];
      const Vec3 to_end = pose.global_positions[end] - joint;
      const Vec3 to_target = target - joint;
      // A joint sitting on the end effector or on the target has no direction to turn.
      if (to_end.squaredNorm() == 0.0 || to_target.squaredNorm() == 0.0) continue;
      // Turn joint i in world space: global'[i] = arc * global[i], expressed back in its
      // parent's frame as the new local rotation; then forward kinematics from joint i.
      const Quat global = shortest_arc(to_end, to_target) * pose.global_rotations[i];
      pose.local_rotations[i] =
          i == 0 ? global.normalized() : (pose.global_rotations[i - 1].conjugate() * global).normalized();
      forward_kinematics(chain, pose, i);
    }
    ++result.iterations;
    result.error = (pose.global_positions[end] - target).norm();
  }
  result.converged = result.error <= options.tolerance;
  return result;
}

}  // namespace animkit
