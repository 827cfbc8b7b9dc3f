#pragma once
// An image's skeleton as pen strokes (the lab's bonus task): grayscale -> threshold (Otsu by
// default) -> speck removal -> thinning -> skeleton graph -> strokes covering every edge ->
// smoothing. Resampling and placement on the plane come after (trajectory.h).
#include <Eigen/Geometry>
#include <optional>

#include "animkit/core/result.h"
#include "animkit/trajectory/binary_image.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// Largest image side accepted (pixels): thinning is O(pixels) per pass.
constexpr int kMaxImageSide = 4096;

/// Settings of image_to_strokes(): thresholding, speck removal, thinning and smoothing.
struct ImageStrokeOptions {
  std::optional<int> threshold = std::nullopt;  ///< gray level 0..254 splitting ink and paper; nothing = Otsu
  InkPolarity polarity = InkPolarity::automatic;         ///< which side of the threshold is ink
  ThinningMethod thinning = ThinningMethod::zhang_suen;  ///< the thinning algorithm
  /// Ink pieces smaller than this fraction of the largest piece (and any under 4 pixels) are
  /// specks of noise and dropped before thinning. In [0, 1).
  double speck_fraction = 0.02;
  /// Moving-average radius (skeleton pixels) that smooths the staircase of pixel paths;
  /// ends and corners stay put. >= 0.
  int smoothing_radius = 2;

  /// The first problem (a threshold outside 0..254, speck_fraction outside [0, 1), a negative
  /// smoothing_radius), or nothing.
  std::optional<Error> validate() const;
};

/// An image's strokes, with what the pipeline chose and removed on the way.
struct ImageStrokes {
  Strokes strokes;  ///< drawing coordinates: x right, y up, one unit per pixel
  /// The ink's extent in the same coordinates: the frame to fit when placing the drawing.
  Eigen::AlignedBox2d extent;
  int threshold = 0;  ///< the gray level used
  /// Ink components dropped as specks before thinning.
  int specks_removed = 0;
  int spurs_removed = 0;  ///< short skeleton branches dropped (see prune_spurs)
  BinaryImage skeleton;   ///< the thinned ink, for inspection and tests
};

/// Errors: an empty image or one larger than kMaxImageSide, an image of a single gray level
/// ("nothing to draw"), no ink left after thresholding and speck removal, bad options.
Result<ImageStrokes> image_to_strokes(const GrayImage& image,
                                      const ImageStrokeOptions& options = {});

}  // namespace animkit
