#include "animkit/kinematics/skeleton_drawing_session.h"

#include <algorithm>
#include <string>

#include "animkit/kinematics/tree_ik_solver.h"
#include "drawing_loop.h"

namespace animkit {

std::optional<Error> SkeletonDrawingOptions::validate() const {
  if (laps < 1) return Error{"laps must be at least 1, got " + std::to_string(laps)};
  // Every solver checks the same two numbers with the same words (tree_ik_common).
  FabrikTreeSettings stopping;
  stopping.max_iterations = max_iterations;
  stopping.tolerance = tolerance;
  return stopping.validate();
}

Result<DrawingRun> run_skeleton_drawing(const Skeleton& skeleton, int effector,
                                        std::span<const JointLimit> limits,
                                        std::span<const Vec3> targets,
                                        const SkeletonDrawingOptions& options,
                                        std::span<const char> pen_down) {
  if (auto error = options.validate()) return fail(error->message);
  if (auto error = validate_drawing_targets(targets, options.laps, pen_down)) {
    return fail(error->message);
  }

  TreeIkSolvers solvers;
  solvers.set_stopping(options.max_iterations, options.tolerance);
  Effector target{effector, Vec3::Zero()};
  const TreeIkProblem problem{std::span<const Effector>(&target, 1), limits};
  DrawingRun run;
  auto last = detail::run_drawing_frames(
      targets, options.laps, options.warm_start, pen_down, skeleton_rest_pose(skeleton),
      [&](SkeletonPose& pose, const Vec3& position) -> Result<IkResult> {
        target.position = position;
        auto solved = solve_tree_ik(options.solver, skeleton, problem, solvers, pose);
        if (!solved) return fail(solved.error().message);
        return IkResult{solved->iterations, solved->error, solved->converged, solved->reachable};
      },
      [&](const SkeletonPose& pose) {
        return pose.global_positions[static_cast<std::size_t>(effector)];
      },
      run);
  if (!last) return fail(last.error().message);
  run.final_pose = Pose{last->local_rotations, last->global_rotations, last->global_positions};
  return run;
}

}  // namespace animkit
