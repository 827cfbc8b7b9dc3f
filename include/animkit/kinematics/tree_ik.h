#pragma once
// What every IK solver on a skeleton tree shares: effectors with their targets, the
// joint limits the solver enforces inside its iterations, and the result. FABRIK for trees,
// CCD over trees and damped least squares take the same arguments in the same order:
//
//   Result<TreeIkResult> solve_X(const Skeleton& skeleton, const TreeIkProblem& problem,
//                                const XSettings& settings, XWorkspace& workspace,
//                                SkeletonPose& pose);
//
// so the viewer and the CLI switch between them with TreeIkSolverKind. The pose is read as the
// starting guess and overwritten with the solution (FK already run). Roots never move: their
// local translations are kept. Every joint, roots included, may turn (never translate), in
// every solver (FABRIK, CCD, DLS and SDLS alike): the lab's chain turns its root joint to swing
// the first bone, and tree_ik_reachable() counts the root's child bones in the reach. A root
// that must not turn gets a limit with no range (e.g. a BallLimit with swing_angle = 0 and a
// zero twist range).
//
// Joint limits apply to a joint's rotation relative to its rest rotation,
//   q_rel = rest_rotations[i]^-1 * local_rotations[i]
// (joint_limits.h), so a skeleton at rest is inside every limit that contains the identity.
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"
#include "animkit/kinematics/joint_limits.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit {

/// One end effector: a joint and where it should be.
struct Effector {
  int joint = -1;                ///< index of the joint in the skeleton; not a root
  Vec3 position = Vec3::Zero();  ///< world space, scene units, finite
  /// World orientation the joint should take (unit); none (the default): position only.
  std::optional<Quat> orientation = std::nullopt;
  double weight = 1.0;  ///< relative importance among effectors, finite, > 0
};

/// The inputs of a solve besides the pose.
struct TreeIkProblem {
  std::span<const Effector> effectors;  ///< at least one; joints distinct
  /// One limit per joint (FreeJoint where none), or empty: every joint free.
  std::span<const JointLimit> limits = {};
};

/// What a solve did.
struct TreeIkResult {
  int iterations = 0;  ///< full iterations run (a sweep, a FABRIK pass, a DLS step)
  /// Iterations another solver ran after those to finish the solve (FABRIK's DLS finish;
  /// not counted in `iterations`).
  int finish_iterations = 0;
  double error = 0.0;  ///< largest |effector joint - target position| (scene units)
  /// Largest angle (rad) between an effector joint's orientation and its target, over the
  /// effectors that have one (0 when none has).
  double orientation_error = 0.0;
  bool converged = false;  ///< error <= tolerance and orientation_error <= angular tolerance
  /// False when some target lies farther from the nearest fixed root above its effector than
  /// the bones between them reach.
  bool reachable = true;
};

/// The first problem with a problem for this skeleton and pose: pose sizes, an effector on a
/// root or out of range or repeated, a non-finite target, a non-unit orientation, a weight not
/// > 0, a limits span of the wrong size or an invalid limit.
std::optional<Error> validate_tree_ik(const Skeleton& skeleton, const TreeIkProblem& problem,
                                      const SkeletonPose& pose);

/// The position and orientation errors of `pose` (FK run) against the effectors:
/// TreeIkResult::error and orientation_error.
struct TreeIkErrors {
  double position = 0.0;     ///< largest |effector joint - target position| (scene units)
  double orientation = 0.0;  ///< largest angle to a target orientation, radians in [0, pi]
};
TreeIkErrors tree_ik_errors(const SkeletonPose& pose, std::span<const Effector> effectors);

/// Whether every target is within reach (TreeIkResult::reachable).
bool tree_ik_reachable(const Skeleton& skeleton, const SkeletonPose& pose,
                       std::span<const Effector> effectors);

/// Per-joint scratch that every tree solver's workspace holds; its contents are the solver's
/// business between calls. Sized once per skeleton, so a solve does not allocate.
struct TreeIkScratch {
  std::vector<double> subtree_weight;      ///< sum of effector weights at joint i and below
  std::vector<double> below_weight;        ///< sum of effector weights strictly below joint i
  std::vector<int> effector_of;            ///< index into the effectors of joint i's, or -1
  std::vector<Quat> best_local_rotations;  ///< the best pose seen during the solve
  std::vector<char> marks;                 ///< per-joint flags (e.g. "in this subtree")

  /// Sizes every array for `joint_count` joints (allocates only when the size changes).
  void resize(int joint_count);
  /// Whether the arrays have `joint_count` entries.
  bool fits(int joint_count) const;
};

/// Joint i's rotation relative to its rest rotation (what its limit constrains).
inline Quat relative_to_rest(const Skeleton& skeleton, const SkeletonPose& pose, int joint) {
  return skeleton.rest_rotations()[joint].conjugate() * pose.local_rotations[joint];
}

}  // namespace animkit
