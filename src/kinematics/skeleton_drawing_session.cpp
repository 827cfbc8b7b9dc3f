#include "animkit/kinematics/skeleton_drawing_session.h"

#include <algorithm>
#include <chrono>
#include <string>

#include "animkit/core/quaternion_math.h"
#include "animkit/kinematics/tree_ik_solver.h"

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
  const SkeletonPose rest = skeleton_rest_pose(skeleton);
  SkeletonPose pose = rest;
  SkeletonPose previous = rest;
  Effector target{effector, Vec3::Zero()};
  const TreeIkProblem problem{std::span<const Effector>(&target, 1), limits};
  DrawingRun run;
  run.frames.reserve(targets.size() * static_cast<std::size_t>(options.laps));
  for (int lap = 0; lap < options.laps; ++lap) {
    for (std::size_t t = 0; t < targets.size(); ++t) {
      if (t == 0 || !options.warm_start) pose = rest;
      target.position = targets[t];
      const auto start = std::chrono::steady_clock::now();
      auto solved = solve_tree_ik(options.solver, skeleton, problem, solvers, pose);
      const auto stop = std::chrono::steady_clock::now();
      if (!solved) return fail(solved.error().message);

      DrawingFrame frame;
      frame.lap = lap;
      frame.target = targets[t];
      frame.pen_down = pen_down.empty() || pen_down[t] != 0;
      frame.end_effector = pose.global_positions[static_cast<std::size_t>(effector)];
      frame.ik = IkResult{solved->iterations, solved->error, solved->converged, solved->reachable};
      frame.joint_step_rad =
          t == 0 ? 0.0 : largest_rotation_change(previous.local_rotations, pose.local_rotations);
      frame.solve_time_us = std::chrono::duration<double, std::micro>(stop - start).count();
      frame.joint_positions = pose.global_positions;
      run.frames.push_back(std::move(frame));
      previous = pose;
    }
  }
  run.final_pose = Pose{pose.local_rotations, pose.global_rotations, pose.global_positions};
  return run;
}

}  // namespace animkit
