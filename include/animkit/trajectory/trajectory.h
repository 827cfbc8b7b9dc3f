#pragma once
// From a drawing to the arm's targets: the strokes are scaled and placed on the plane y = 0,
// and joined by pen-up travel, so the arm moves between strokes without drawing.
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "animkit/core/types.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// The arm's targets in drawing order (world space), one per frame, each with the pen state.
struct Trajectory {
  std::vector<Vec3> targets;   ///< world positions (scene units), one per frame
  std::vector<char> pen_down;  ///< per target: 1 draws, 0 travels between strokes

  /// A single pen-down stroke through `points` (the lab's shapes).
  static Trajectory all_pen_down(std::vector<Vec3> points);
};

/// Where a drawing goes on the plane y = 0: a square centred at (center_x, 0, center_z).
struct DrawingBox {
  /// x of the square's centre (scene units, finite).
  double center_x = 0.0, center_z = 0.0;  ///< z of the square's centre (scene units, finite)
  double half_extent = 0.6;  ///< the drawing's larger side spans 2 * half_extent; > 0
};

/// Scales the strokes uniformly (keeping proportions) and centres them in `box`; the
/// drawing's u runs along +x and its v (up in the picture) along -z, so a camera looking from
/// +z down at the plane sees the drawing upright. `frame` is the drawing's extent to fit
/// (default: the strokes' bounds; an image passes its ink's). Returns plane coordinates
/// (x, z). Errors: no points at all, a non-finite point or extent, a bad box.
Result<Strokes> fit_to_box(const Strokes& strokes, const DrawingBox& box,
                           const std::optional<Eigen::AlignedBox2d>& frame = std::nullopt);

/// The largest box the lab-style arm reaches comfortably: centred under the root, its corners
/// at `fill` (0..1] of the radius where the plane y = plane_y leaves the arm's reach.
DrawingBox reachable_box(const Vec3& root, double reach, double plane_y = 0.0, double fill = 0.7);

/// How to_trajectory() moves the pen between strokes.
struct TravelOptions {
  double pen_lift = 0.05;  ///< height of pen-up travel above the plane (scene units), >= 0
  double spacing = 0.02;   ///< distance between travel targets (scene units), > 0

  /// The first problem (a negative or non-finite pen_lift, a spacing not positive and
  /// finite), or nothing.
  std::optional<Error> validate() const;
};

/// Targets for strokes in plane coordinates (x, z) on y = 0: every stroke's points with the
/// pen down, and between strokes a lift, a straight move and a drop with the pen up.
/// Errors: bad travel options, a drawing with no points.
Result<Trajectory> to_trajectory(const Strokes& plane_strokes, const TravelOptions& travel = {});

/// The strokes a trajectory draws: runs of pen-down targets, in plane coordinates (x, z).
Strokes pen_down_strokes(const Trajectory& trajectory);

}  // namespace animkit
