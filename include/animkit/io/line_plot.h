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

struct PlotColor {
  std::uint8_t r = 0, g = 0, b = 0;
};

struct PlotAxis {
  std::string label;
  double min = 0.0, max = 1.0;  ///< the visible range, min < max (both > 0 on a log axis)
  bool log10 = false;           ///< decades as ticks, with labels 10^k
};

/// One polyline in data coordinates, cut where it leaves the axes' ranges (a value <= 0 on a
/// log axis lies below its minimum).
struct PlotSeries {
  std::vector<Point2> points;
  PlotColor color;
  double width = 1.0;    ///< pixels, > 0
  double opacity = 1.0;  ///< in (0, 1]
  bool dashed = false;
};

struct LegendEntry {
  std::string label;
  PlotColor color;
  double width = 2.0;  ///< of its sample line (pixels)
  bool dashed = false;
};

struct LinePlot {
  std::string title;
  PlotAxis x, y;
  std::vector<PlotSeries> series;  ///< drawn in order, later ones on top
  std::vector<LegendEntry> legend;
  /// Lines of grey text under the legend (e.g. what thin and bold lines mean).
  std::vector<std::string> notes;
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
