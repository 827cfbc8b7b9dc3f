#pragma once
// A user's own drawing as a CSV file: one point per line, "x,z" on the plane y = 0 (or any
// units: the drawing is scaled to fit), a blank line lifts the pen (starts a new stroke),
// lines starting with # are comments.
#include <filesystem>

#include "animkit/core/result.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// The strokes of the file, in drawing coordinates (u = x, v = -z, so the picture keeps its
/// orientation when placed back on the plane). Errors name the file and the line: missing
/// file, a line that is not two finite numbers, no points at all.
Result<Strokes> read_curve_csv(const std::filesystem::path& path);

}  // namespace animkit
