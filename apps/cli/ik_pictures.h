#pragma once
#include <filesystem>
#include <optional>
#include <span>

#include "animkit/kinematics/drawing_session.h"
#include "animkit/trajectory/trajectory.h"
#include "picture_output.h"

namespace animkit::cli {

/// Frames per second of an IK video: one target per frame, as the lab's app draws.
constexpr double kIkVideoFps = 60.0;

/// Renders the run's video frames (if asked for) and DIR/drawing.png: the arm at frame
/// `picture_frame` (default and beyond the end: the last) over the targets and the strokes
/// its lap has drawn so far, from a camera framing the whole run.
Result<void> render_ik_pictures(const Trajectory& trajectory, const DrawingRun& run,
                                PictureOutput& pictures, const std::filesystem::path& out,
                                std::optional<int> picture_frame = std::nullopt);

}  // namespace animkit::cli
