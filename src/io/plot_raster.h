#pragma once
// A software rasterizer for plots: polygons filled by the nonzero winding rule, anti-aliased
// by counting covered samples on a 4 x 4 grid per pixel, and blended over the picture with an
// opacity. Lines are filled as one quad per segment plus a small disc per joint, all wound the
// same way, so a translucent polyline covers each pixel once however its segments overlap.
#include <cstdint>
#include <vector>

#include "animkit/core/image.h"
#include "animkit/io/line_plot.h"

namespace animkit::plot {

using Polygon = std::vector<Point2>;  ///< pixels, closed implicitly

class Canvas {
 public:
  Canvas(int width, int height, PlotColor background);

  /// Fills the union of `polygons` (nonzero rule) with `color` at `opacity` in (0, 1].
  void fill(const std::vector<Polygon>& polygons, PlotColor color, double opacity);
  /// Strokes a polyline `width` pixels wide; `dashed`: 6 px on, 4 px off.
  void stroke(const std::vector<Point2>& points, PlotColor color, double width, double opacity,
              bool dashed);

  const Image& image() const { return image_; }

 private:
  Image image_;
  std::vector<std::uint16_t> coverage_;  // covered samples per pixel of the current fill
};

}  // namespace animkit::plot
