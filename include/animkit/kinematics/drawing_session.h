#pragma once
// A drawing session: the arm follows a list of targets, one IK solve per frame, as the lab's
// app does. Records what each frame did so the lab's questions can be answered by measurement.
#include <span>
#include <vector>

#include "animkit/kinematics/ik_solver.h"

namespace animkit {

/// How run_drawing() draws: the solver and its options, the laps, and warm or cold starts.
struct DrawingOptions {
  IkSolverKind solver = IkSolverKind::ccd;  ///< the lab's first solver
  IkOptions ik;                             ///< lab defaults: 100 iterations, eps 1e-4
  int laps = 1;                             ///< times the whole target list is drawn; >= 1
  /// true (the lab): each frame starts from the previous frame's pose, and the pose is reset
  /// to rest when a lap starts. false: every frame starts from the rest pose (cold start).
  bool warm_start = true;

  /// The first problem (laps < 1, then ik.validate()'s), or nothing.
  std::optional<Error> validate() const;
};

/// One frame: one target, one solve.
struct DrawingFrame {
  int lap = 0;                       ///< lap the frame belongs to, from 0
  Vec3 target = Vec3::Zero();        ///< the frame's target (world, scene units)
  bool pen_down = true;              ///< false while travelling between strokes
  Vec3 end_effector = Vec3::Zero();  ///< after the solve (world)
  IkResult ik;                       ///< what the solve reported (iterations, error, ...)
  /// Largest change of any joint's local rotation since the previous frame of the same lap
  /// (radians; 0 on a lap's first frame): the frame-to-frame jitter of the lab's question 3.
  double joint_step_rad = 0.0;
  double solve_time_us = 0.0;         ///< wall-clock time of the solve (microseconds)
  std::vector<Vec3> joint_positions;  ///< pose after the solve, for drawing the arm (world)
};

/// Everything a session recorded: its frames and the pose it ended in.
struct DrawingRun {
  std::vector<DrawingFrame> frames;  ///< laps * targets frames, in order
  Pose final_pose;                   ///< the pose after the last frame's solve
};

/// Most frames a session runs (laps x targets): each frame keeps its pose for drawing.
constexpr long long kMaxDrawingFrames = 10'000'000;

/// The checks every drawing session makes of its input: an empty target list, a NaN/inf
/// target (naming its index), more than kMaxDrawingFrames frames (laps x targets), a pen list
/// whose size is not the targets'. Shared with run_skeleton_drawing().
std::optional<Error> validate_drawing_targets(std::span<const Vec3> targets, int laps,
                                              std::span<const char> pen_down);

/// Runs the session. Errors: empty target list, a NaN/inf target (naming its index), bad
/// options, more than kMaxDrawingFrames frames, a pen list whose size is not the targets'.
/// `pen_down` (one flag per target, or empty for all down) is recorded in the frames.
Result<DrawingRun> run_drawing(const Chain& chain, std::span<const Vec3> targets,
                               const DrawingOptions& options = {},
                               std::span<const char> pen_down = {});

/// The drawn path of a run: the end effector's positions while the pen is down, one polyline
/// per stroke (a new one at each pen-up and at each lap, where the arm is reset).
std::vector<std::vector<Vec3>> drawn_strokes(std::span<const DrawingFrame> frames);

/// Aggregate numbers of a run (the metrics the CLI writes and docs/results.md quotes).
struct DrawingSummary {
  int targets = 0;                  ///< frames solved
  double converged_fraction = 0.0;  ///< frames with error <= tolerance, in [0, 1]
  int unreachable_targets = 0;      ///< frames whose target no pose reaches
  double iterations_mean = 0.0;     ///< mean iterations per frame
  double iterations_median = 0.0;   ///< median iterations per frame
  int iterations_max = 0;           ///< most iterations of any frame
  double error_mean = 0.0;          ///< mean IkResult::error, |end effector - target| (scene units)
  double error_max = 0.0;           ///< largest IkResult::error (scene units)
  double max_joint_step_rad = 0.0;  ///< largest DrawingFrame::joint_step_rad (radians)
  /// Median wall-clock time of a frame's solve (microseconds).
  double solve_time_us_median = 0.0;
  /// Mean wall-clock time of a frame's solve (microseconds).
  double solve_time_us_mean = 0.0;
};

/// The summary of `run`'s frames; every field 0 for a run without frames.
DrawingSummary summarize(const DrawingRun& run);

}  // namespace animkit
