#pragma once
// A user's own drawing as a CSV file: one point per line, "x,z" on the plane y = 0 (or any
// units: the drawing is scaled to fit), a blank line lifts the pen (starts a new stroke),
// lines starting with # are comments.
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "animkit/core/result.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// Largest curve file read: far more points than a drawing can use (see kMaxDrawingTargets).
constexpr std::uintmax_t kMaxCurveFileBytes = 256u << 20;

/// The strokes of CSV `text`, in drawing coordinates (u = x, v = -z, so the picture keeps its
/// orientation when placed back on the plane). `name` (the file's) starts every error, which
/// names the line: a line that is not two finite numbers or holds a NUL byte, no points at all.
/// The offending line is shown through quote_input (escaped, cut when long).
Result<Strokes> parse_curve_csv(std::string_view text, std::string_view name);

/// parse_curve_csv of the file's bytes; also errors for a missing, unreadable or huge file.
Result<Strokes> read_curve_csv(const std::filesystem::path& path);

}  // namespace animkit
