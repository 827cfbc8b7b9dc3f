#pragma once
// A LinePlot laid out in pixels (y down, origin top left): the paths and texts both the SVG
// writer and the software rasterizer draw, so the two pictures agree.
#include <string>
#include <vector>

#include "animkit/io/line_plot.h"

namespace animkit::plot {

struct Path {
  std::vector<Point2> points;  ///< pixels
  PlotColor color;
  double width = 1.0;
  double opacity = 1.0;
  bool dashed = false;
};

enum class Anchor { start, middle, end };

struct Text {
  std::string text;  ///< UTF-8
  Point2 at;         ///< the baseline's anchor point (pixels)
  double size = 13;  ///< em in pixels
  Anchor anchor = Anchor::start;
  bool vertical = false;  ///< rotated a quarter turn anticlockwise (reads bottom to top)
  PlotColor color;
};

struct Scene {
  int width = 0, height = 0;
  std::vector<Path> paths;
  std::vector<Text> texts;
};

/// Lays `plot` out (it must be valid): frame, grid lines, ticks and their labels, axis labels,
/// title, the series cut at the frame's edges, the legend and its notes.
Scene layout(const LinePlot& plot);

/// Tick positions of an axis in data units: decades on a log axis, 1-2-5 steps on a linear one
/// (about `target` of them).
std::vector<double> major_ticks(const PlotAxis& axis, int target = 6);

/// A tick's label: "1", "10⁻³" (Unicode superscripts) on a log axis, "%g" on a linear one.
std::string tick_label(const PlotAxis& axis, double value);

}  // namespace animkit::plot
