#pragma once
// Drawings made of strokes (docs/drawings.md): polylines drawn with the pen down, in the
// drawing's own 2D frame (u to the right, v up, as in a picture or a glyph), and the tools to
// sample them evenly and measure how evenly they are sampled.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "animkit/core/result.h"

namespace animkit {

using Point2 = Eigen::Vector2d;
/// One pen-down polyline. A closed stroke repeats its first point at the end.
using Stroke = std::vector<Point2>;
using Strokes = std::vector<Stroke>;

/// How evenly a drawing is sampled: statistics of the distances between consecutive points
/// of each stroke (pen-up gaps between strokes are not segments).
struct SpacingStats {
  int segments = 0;   ///< distances measured; when there are none, every field is 0
  double mean = 0.0;  ///< mean segment length (drawing units)
  /// Shortest segment (drawing units).
  double min = 0.0, max = 0.0;  ///< longest segment (drawing units)
  double cv = 0.0;  ///< coefficient of variation: standard deviation / mean
};
SpacingStats spacing_stats(const Strokes& strokes);

/// Total length of a stroke.
double stroke_length(const Stroke& stroke);

/// Settings of resample().
struct ResampleOptions {
  double spacing = 0.01;  ///< target distance between samples (drawing units), > 0
  /// A point where the direction turns by more than this (radians) is a corner and is kept
  /// as a sample, so squares stay square. In (0, pi]; default 30 degrees.
  double corner_angle = 0.5235987755982988;

  /// The first problem (a spacing not positive and finite, a corner_angle outside (0, pi]), or
  /// nothing.
  std::optional<Error> validate() const;
};

/// Resamples a stroke by arc length: corners (found at the scale of `spacing`) and both ends
/// are kept, and each piece between them is cut into equal parts no longer than `spacing` (so
/// spacing varies only where a piece is shorter than a whole number of spacings). Duplicate points
/// are dropped first; a stroke of fewer than 2 distinct points comes back as its first point.
Stroke resample(const Stroke& stroke, const ResampleOptions& options);
Strokes resample(const Strokes& strokes, const ResampleOptions& options);

/// Indices of the corners of a stroke, first and last points excluded (a closed stroke's start
/// counts when it turns there): points where the direction from `scale` of arc behind to
/// `scale` ahead turns by more than `corner_angle` radians, the sharpest of each bend. The
/// scale makes a pixel staircase smooth and a real corner sharp; 0 compares neighbours.
std::vector<std::size_t> find_corners(const Stroke& stroke, double corner_angle,
                                      double scale = 0.0);

/// Moving-average smoothing over `radius` neighbours on each side, ends (and the corners
/// given) held fixed; for the staircase of pixel skeletons. radius 0 returns the stroke.
Stroke smooth(const Stroke& stroke, int radius, const std::vector<std::size_t>& fixed = {});

}  // namespace animkit
