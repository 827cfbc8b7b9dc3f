#pragma once
// A small line plot (axes with ticks and labels, a linear or log10 scale per axis, polylines,
// a legend) drawn to SVG text and to an RGBA image without OpenGL: the image is rasterized in
// software (anti-aliased by supersampling) with its text set from the glyph outlines of
// text_strokes.h, so both files show the same picture. For the convergence study's plots.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "animkit/core/image.h"
#include "animkit/core/result.h"
#include "animkit/io/text_strokes.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// An opaque RGB colour, 8 bits per channel; black by default.
struct PlotColor {
  /// Red, 0..255.
  std::uint8_t r = 0, g = 0, b = 0;  ///< blue, 0..255
  /// \var g
  /// Green, 0..255.
};

/// One axis of a plot: its label, visible range and scale.
struct PlotAxis {
  std::string label;  ///< written along the axis (the y label rotated)
  /// Lower end of the visible range (> 0 on a log axis).
  double min = 0.0, max = 1.0;  ///< the visible range, min < max (both > 0 on a log axis)
  bool log10 = false;           ///< decades as ticks, with labels 10^k
};

/// One polyline in data coordinates, cut where it leaves the axes' ranges (a value <= 0 on a
/// log axis lies below its minimum).
struct PlotSeries {
  std::vector<Point2> points;  ///< (x, y) in data coordinates, joined in order
  PlotColor color;             ///< the line's colour
  double width = 1.0;    ///< pixels, > 0
  double opacity = 1.0;  ///< in (0, 1]
  bool dashed = false;   ///< dashed instead of solid
};

/// One line of the legend: a short sample line and its label.
struct LegendEntry {
  std::string label;   ///< text beside the sample line
  PlotColor color;     ///< of its sample line
  double width = 2.0;  ///< of its sample line (pixels)
  bool dashed = false;  ///< whether its sample line is dashed
};

/// A whole plot: title, axes, series, legend and picture size.
struct LinePlot {
  std::string title;  ///< centred above the frame
  /// The horizontal axis.
  PlotAxis x, y;                   ///< the vertical axis
  std::vector<PlotSeries> series;  ///< drawn in order, later ones on top
  std::vector<LegendEntry> legend;  ///< top to bottom, right of the frame
  /// Lines of grey text under the legend (e.g. what thin and bold lines mean).
  std::vector<std::string> notes;
  /// Picture width in pixels, in [320, 4096].
  int width = 1000, height = 620;  ///< pixels, each in [320, 4096]

  /// The first problem (bad range or size, a non-finite point, a bad width), or nothing.
  std::optional<Error> validate() const;
};

/// The plot as a standalone SVG document (text in DejaVu Sans, falling back to sans-serif).
/// The plot must be valid.
std::string line_plot_svg(const LinePlot& plot);

/// The plot as an image. Errors: the font's (see text_strokes) and an invalid plot.
Result<Image> line_plot_image(const LinePlot& plot, const TextOptions& font = {});

}  // namespace animkit
