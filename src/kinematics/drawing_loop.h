#pragma once
// The lab's drawing loop, shared by the chain's session (drawing_session.cpp) and the
// skeleton's (skeleton_drawing_session.cpp), so that both record their frames the same way:
// laps over the targets; the arm back at rest when a shape starts over, or before every target
// with a cold start; one timed solve per target; each frame with its largest joint step.
#include <chrono>
#include <span>
#include <utility>

#include "animkit/core/quaternion_math.h"
#include "animkit/core/result.h"
#include "animkit/kinematics/drawing_session.h"

namespace animkit::detail {

/// Appends laps x targets frames to `run` and returns the last pose. `PoseT` has
/// local_rotations and global_positions; `solve(pose, target)` moves `pose` to the target and
/// returns Result<IkResult>; `end_effector(pose)` is where the pen is. The inputs are
/// validated by the caller (validate_drawing_targets).
template <class PoseT, class Solve, class EndEffector>
Result<PoseT> run_drawing_frames(std::span<const Vec3> targets, int laps, bool warm_start,
                                 std::span<const char> pen_down, const PoseT& rest, Solve&& solve,
                                 EndEffector&& end_effector, DrawingRun& run) {
  run.frames.reserve(targets.size() * static_cast<std::size_t>(laps));
  PoseT pose = rest;
  PoseT previous = rest;
  for (int lap = 0; lap < laps; ++lap) {
    for (std::size_t t = 0; t < targets.size(); ++t) {
      if (t == 0 || !warm_start) pose = rest;
      const auto start = std::chrono::steady_clock::now();
      Result<IkResult> solved = solve(pose, targets[t]);
      const auto stop = std::chrono::steady_clock::now();
      if (!solved) return fail(solved.error().message);

      DrawingFrame frame;
      frame.lap = lap;
      frame.target = targets[t];
      frame.pen_down = pen_down.empty() || pen_down[t] != 0;
      frame.end_effector = end_effector(pose);
      frame.ik = *solved;
      frame.joint_step_rad =
          t == 0 ? 0.0 : largest_rotation_change(previous.local_rotations, pose.local_rotations);
      frame.solve_time_us = std::chrono::duration<double, std::micro>(stop - start).count();
      frame.joint_positions = pose.global_positions;
      run.frames.push_back(std::move(frame));
      previous = pose;
    }
  }
  return pose;
}

}  // namespace animkit::detail
