#pragma once
// Where a drawing comes from (a built-in shape, text, an image, an MNIST digit, a CSV of
// points) and how it becomes the arm's targets: placed in the arm's reach on the plane y = 0,
// resampled evenly, strokes joined by pen-up travel. One entry point for the CLI and viewer.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "animkit/io/text_strokes.h"
#include "animkit/kinematics/chain.h"
#include "animkit/trajectory/image_strokes.h"
#include "animkit/trajectory/trajectory.h"

namespace animkit {

/// What a drawing is made from: a built-in shape, text, an image file (read as gray), one image
/// of an MNIST file, or a CSV of points (curve_csv.h).
enum class DrawingSourceKind { shape, text, image, mnist, curve };

/// Where a drawing comes from: its kind and the fields that kind reads (the others are ignored).
struct DrawingSource {
  DrawingSourceKind kind = DrawingSourceKind::shape;  ///< which of the fields below are read
  std::string shape = "circle";  ///< kind shape: a lab shape or "spiral" (builtin_shape_names)
  std::string text;              ///< kind text: UTF-8, '\n' starts a new line
  TextOptions text_options;      ///< kind text: font, tolerance, centre lines
  std::filesystem::path file;    ///< kinds image, mnist, curve
  int index = 0;                 ///< kind mnist: which image of the file
  ImageStrokeOptions image;      ///< kinds image, mnist
};

/// How a drawing's strokes are placed and sampled for the arm.
struct DrawingLayout {
  /// Resample every stroke by arc length to this spacing (scene units, > 0). Text, images and
  /// curves default to 0.01; built-in shapes keep the lab's own sampling unless it is given.
  std::optional<double> spacing = std::nullopt;
  /// Where text, images and curves go; default reachable_box() of the arm (fill 0.7).
  /// Built-in shapes keep the lab's coordinates.
  std::optional<DrawingBox> box = std::nullopt;
  TravelOptions travel = {};  ///< pen-up moves between strokes: lift height and target spacing
};

/// A drawing ready for the arm: its targets (strokes on the plane y = 0, pen-up travel above it)
/// and how it was sampled.
struct PreparedDrawing {
  std::string name;  ///< e.g. "star", "text QD", "image seven.png", "mnist digits.idx #3"
  Trajectory trajectory;        ///< pen-down stroke targets joined by pen-up travel (scene units)
  int strokes = 0;              ///< pen-down strokes in the trajectory
  SpacingStats spacing_before;  ///< of the placed strokes before resampling (scene units)
  SpacingStats spacing_after;   ///< of the strokes the arm is given
};

/// Most targets a prepared drawing may have (a spacing that asks for more is refused).
constexpr double kMaxDrawingTargets = 1e6;

/// Built-in shapes, in menu order: the lab's five, then "spiral" (unevenly sampled).
std::vector<std::string> builtin_shape_names();

/// Reads and prepares a drawing for `chain`. Errors name the problem: an unknown shape, a
/// file that cannot be read (see read_gray_image, read_mnist_image, read_curve_csv,
/// text_strokes), an image with nothing to draw, bad layout options.
Result<PreparedDrawing> prepare_drawing(const DrawingSource& source, const DrawingLayout& layout,
                                        const Chain& chain);

}  // namespace animkit
