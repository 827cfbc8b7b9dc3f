#pragma once
// The lab's drawing session (drawing_session.h) on a skeleton: one effector joint follows the
// targets, one tree IK solve per frame, with joint limits enforced inside the solver. The lab's
// arm as a one-branch skeleton (skeleton_desc_from_chain) with a limits file is how
// `animkit ik --limits` asks the lab's three questions again (convergence, unreachable targets,
// jitter). The frames are the chain session's, so its summary and reports apply unchanged.
#include <span>

#include "animkit/kinematics/drawing_session.h"
#include "animkit/kinematics/joint_limits.h"
#include "animkit/kinematics/skeleton.h"
#include "animkit/kinematics/tree_ik_solver.h"

namespace animkit {

/// How run_skeleton_drawing() draws: the tree solver and its stopping rule, laps, warm starts.
struct SkeletonDrawingOptions {
  TreeIkSolverKind solver = TreeIkSolverKind::ccd;  ///< the lab's first solver
  int max_iterations = 100;                         ///< per target, >= 1 (the lab's)
  double tolerance = 1e-4;                          ///< scene units, > 0 (the lab's)
  int laps = 1;                                     ///< >= 1, as DrawingOptions::laps
  bool warm_start = true;                           ///< as DrawingOptions::warm_start

  /// The first problem ("laps must be at least 1, got 0"), or nothing.
  std::optional<Error> validate() const;
};

/// Runs the session: joint `effector` (not a root) follows `targets` with the solver
/// `options.solver` and one limit per joint in `limits` (or none: every joint free). Frames
/// are recorded as run_drawing() records them: IkResult from the tree result (iterations,
/// error, converged, reachable), joint_step_rad the largest change of any joint's local
/// rotation since the previous frame of the lap, joint_positions every joint's world
/// position; final_pose holds the last pose's rotations and positions. Errors: those of
/// validate_drawing_targets(), bad options, and the solver's (a bad effector or limit).
Result<DrawingRun> run_skeleton_drawing(const Skeleton& skeleton, int effector,
                                        std::span<const JointLimit> limits,
                                        std::span<const Vec3> targets,
                                        const SkeletonDrawingOptions& options = {},
                                        std::span<const char> pen_down = {});

}  // namespace animkit
