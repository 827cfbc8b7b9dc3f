#pragma once
// The files `animkit ik --out DIR` writes, rendered to text from a drawing run:
// metrics.json (names are a contract), path.csv (one row per frame), drawing.svg (top view).
#include <filesystem>
#include <string>
#include <string_view>

#include "animkit/kinematics/drawing_session.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// How a drawing was sampled, for the reports (see PreparedDrawing).
struct DrawingStats {
  int strokes = 0;         ///< pen-down strokes
  int pen_up_targets = 0;  ///< targets of the pen-up travel between strokes
  /// Spacing of the placed strokes before resampling (scene units).
  SpacingStats spacing_before, spacing_after;  ///< spacing of the strokes the arm is given
};

/// What the run was: names printed into the reports.
struct IkRunLabel {
  std::string shape;                    ///< e.g. "star", "text QD"
  std::string solver;                   ///< e.g. "ccd"
  std::optional<DrawingStats> drawing;  ///< strokes and spacing, when known
  /// The joint limits file, when the arm ran as a skeleton with limits (`ik --limits`).
  std::optional<std::string> limits = std::nullopt;
};

/// metrics.json: {"solver", "shape", "targets", "converged_fraction", "unreachable_targets",
/// "iterations": {"mean","median","max"}, "error": {"mean","max"}, "max_joint_step_rad",
/// "solve_time_us": {"median","mean"}, plus the options used and, when the label has them,
/// "limits" (the file, when the label has one; "options" then lacks "fabrik_rotations"),
/// "drawing": {"strokes", "pen_up_targets", "spacing_before"/"spacing_after": {"mean", "cv",
/// "min", "max"}}.
std::string ik_metrics_json(const IkRunLabel& label, const DrawingOptions& options,
                            const DrawingSummary& summary);

/// path.csv: frame, target x,y,z, end effector x,y,z, iterations, error, converged, reachable,
/// pen_down.
std::string ik_path_csv(const DrawingRun& run);

/// drawing.svg: the plane y = 0 seen from above (x to the right, z down), targets in green
/// (pen-up travel targets grey), the drawn end-effector path in red (pen-down strokes only),
/// titled with shape and solver.
std::string ik_drawing_svg(const IkRunLabel& label, const DrawingRun& run);

/// Writes the three files into `dir` (created if needed), each atomically.
Result<void> write_ik_reports(const std::filesystem::path& dir, const IkRunLabel& label,
                              const DrawingOptions& options, const DrawingRun& run);

}  // namespace animkit
