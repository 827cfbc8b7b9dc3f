#pragma once
// A character reaches a hand to a target while both feet stay planted (`animkit
// reach`): one tree IK solve with three effectors, the hand at the target and each foot pinned
// where it stands, the root held where and how it is (roots never translate, and a
// zero-range limit keeps every solver from turning it), the other joints within
// their limits. Which joints move is the solver's choice among those between the root and the
// effectors: with the root fixed, the spine and the arm reach, and the legs keep the feet.
#include <array>
#include <span>

#include "animkit/core/result.h"
#include "animkit/core/types.h"
#include "animkit/kinematics/joint_limits.h"
#include "animkit/kinematics/skeleton.h"
#include "animkit/kinematics/tree_ik.h"
#include "animkit/kinematics/tree_ik_solver.h"

namespace animkit {

/// Settings of reach_hand(): the tree solver, its iteration cap and tolerance, the feet's weight.
struct HandReachSettings {
  /// DLS by default: it moves every joint on the way a little, which is how a body reaches.
  TreeIkSolverKind solver = TreeIkSolverKind::dls;
  int max_iterations = 500;  ///< >= 1
  double tolerance = 1e-4;   ///< scene units (1e-4 m for a skeleton in metres), > 0
  /// The foot effectors weigh this much against the hand's 1 (> 0): the feet must not give.
  double foot_weight = 4.0;

  /// The first problem ("max iterations must be at least 1, got 0"), or nothing.
  std::optional<Error> validate() const;
};

/// What reach_hand() did: the solve, and how far hand, feet and root ended from where wanted.
struct HandReachResult {
  TreeIkResult ik;          ///< the solve (error: the largest over hand and feet)
  double hand_error = 0.0;  ///< |hand - target| after the solve (scene units)
  double foot_drift = 0.0;  ///< largest distance a foot moved (scene units)
  double root_drift = 0.0;  ///< distance the root moved (0 unless a solver broke its promise)
  bool reached = false;     ///< hand_error and foot_drift both within the tolerance
  double solve_ms = 0.0;    ///< wall-clock time of the solve (milliseconds)
};

/// Solves `pose` (FK run; the starting pose, overwritten with the reached one) so that joint
/// `hand` reaches `target` while the joints `feet` stay where they are. `limits`: one per joint
/// of the skeleton, or empty for free joints; only the limits of joints between the root and
/// an effector are used (the others never turn, so the clip's pose of them is kept even where
/// it breaks their limit), and the roots' are replaced by the zero-range limit that holds them. The
/// reached pose is the solver's best even when the target is out of reach (ik.reachable false) or
/// the limits stop the hand short (reached false). Errors: a bad joint index (hand or feet not
/// distinct, a root), a non-finite target, a limits span of the wrong size, bad settings; the
/// pose is then untouched; so is a pose that does not fit the skeleton or whose root rotation
/// is not a unit quaternion. A one-off call: it builds a copy of the skeleton (the roots' rest
/// rotations set to the pose's) and the solvers' workspaces, so it allocates. foot_drift says
/// how far the feet gave (the tests hold them to the tolerance with every solver).
Result<HandReachResult> reach_hand(const Skeleton& skeleton, std::span<const JointLimit> limits,
                                   int hand, std::array<int, 2> feet, const Vec3& target,
                                   const HandReachSettings& settings, SkeletonPose& pose);

}  // namespace animkit
