#include "plot_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace animkit::plot {

namespace {

// Margins around the frame (pixels): tick labels and the y label on the left, the legend on
// the right, the title above, tick labels and the x label below.
constexpr double kLeft = 84, kRight = 262, kTop = 48, kBottom = 64;
constexpr PlotColor kInk{40, 40, 40}, kGrid{225, 225, 225}, kNote{110, 110, 110};

double scaled(const PlotAxis& axis, double value) {
  if (!axis.log10) return value;
  return value > 0.0 ? std::log10(value) : -1e300;
}

// Where `value` falls along the axis, 0 at min and 1 at max; far outside values are held at
// +-1e6 so that they stay finite in pixels.
double fraction(const PlotAxis& axis, double value) {
  const double lo = scaled(axis, axis.min), hi = scaled(axis, axis.max);
  return std::clamp((scaled(axis, value) - lo) / (hi - lo), -1e6, 1e6);
}

struct Frame {
  double x0, y0, x1, y1;
  double px(const PlotAxis& axis, double v) const { return x0 + fraction(axis, v) * (x1 - x0); }
  double py(const PlotAxis& axis, double v) const { return y1 - fraction(axis, v) * (y1 - y0); }
};

// The parts of a polyline inside the frame (Liang and Barsky's clipping of each segment): a
// curve leaving the plot is cut at its edge rather than drawn along it.
std::vector<std::vector<Point2>> clip(const std::vector<Point2>& points, const Frame& f) {
  std::vector<std::vector<Point2>> parts;
  bool open = false;  // the last part ends where the next segment starts
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Point2 a = points[i - 1], d = points[i] - a;
    double t0 = 0.0, t1 = 1.0;
    const auto limit = [&](double p, double q) {  // keeps the t with p t <= q
      if (p == 0.0) return q >= 0.0;
      const double t = q / p;
      if (p < 0.0)
        t0 = std::max(t0, t);
      else
        t1 = std::min(t1, t);
      return t0 <= t1;
    };
    if (!(limit(-d.x(), a.x() - f.x0) && limit(d.x(), f.x1 - a.x()) &&
          limit(-d.y(), a.y() - f.y0) && limit(d.y(), f.y1 - a.y()))) {
      open = false;
      continue;
    }
    if (!open || t0 > 0.0) parts.push_back({a + t0 * d});
    parts.back().push_back(a + t1 * d);
    open = t1 == 1.0;
  }
  return parts;
}

Path line(Point2 a, Point2 b, PlotColor color, double width) {
  return Path{{a, b}, color, width, 1.0, false};
}

// The ticks of a log axis between decades (2 x 10^k ... 9 x 10^k).
std::vector<double> minor_log_ticks(const PlotAxis& axis) {
  std::vector<double> ticks;
  for (int k = static_cast<int>(std::floor(std::log10(axis.min)));
       k <= static_cast<int>(std::ceil(std::log10(axis.max))); ++k) {
    for (int m = 2; m <= 9; ++m) {
      const double v = m * std::pow(10.0, k);
      if (v > axis.min && v < axis.max) ticks.push_back(v);
    }
  }
  return ticks;
}

}  // namespace

std::vector<double> major_ticks(const PlotAxis& axis, int target) {
  std::vector<double> ticks;
  if (axis.log10) {
    const int first = static_cast<int>(std::ceil(std::log10(axis.min) - 1e-9));
    const int last = static_cast<int>(std::floor(std::log10(axis.max) + 1e-9));
    for (int k = first; k <= last; ++k) ticks.push_back(std::pow(10.0, k));
    return ticks;
  }
  // A 1-2-5 step giving about `target` intervals.
  const double raw = (axis.max - axis.min) / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * magnitude;
  for (double m : {1.0, 2.0, 5.0}) {
    if (m * magnitude >= raw) {
      step = m * magnitude;
      break;
    }
  }
  for (double t = std::ceil(axis.min / step - 1e-9); t * step <= axis.max + 1e-9 * step; t += 1)
    ticks.push_back(t * step == 0.0 ? 0.0 : t * step);  // no "-0"
  return ticks;
}

std::string tick_label(const PlotAxis& axis, double value) {
  if (!axis.log10) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
  }
  const int k = static_cast<int>(std::lround(std::log10(value)));
  if (k == 0) return "1";
  if (k == 1) return "10";
  static const char* const kSuperscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string label = "10";
  if (k < 0) label += "⁻";
  for (char digit : std::to_string(std::abs(k))) label += kSuperscript[digit - '0'];
  return label;
}

Scene layout(const LinePlot& plot) {
  Scene scene;
  scene.width = plot.width;
  scene.height = plot.height;
  const Frame f{kLeft, kTop, plot.width - kRight, plot.height - kBottom};

  // Grid lines and ticks first, so the data draws over them.
  for (double t : major_ticks(plot.x)) {
    const double x = f.px(plot.x, t);
    scene.paths.push_back(line({x, f.y0}, {x, f.y1}, kGrid, 1.0));
    scene.paths.push_back(line({x, f.y1}, {x, f.y1 + 5}, kInk, 1.0));
    scene.texts.push_back({tick_label(plot.x, t), {x, f.y1 + 20}, 13, Anchor::middle, false, kInk});
  }
  for (double t : major_ticks(plot.y)) {
    const double y = f.py(plot.y, t);
    scene.paths.push_back(line({f.x0, y}, {f.x1, y}, kGrid, 1.0));
    scene.paths.push_back(line({f.x0 - 5, y}, {f.x0, y}, kInk, 1.0));
    scene.texts.push_back({tick_label(plot.y, t), {f.x0 - 9, y + 5}, 13, Anchor::end, false, kInk});
  }
  if (plot.y.log10) {
    for (double t : minor_log_ticks(plot.y)) {
      const double y = f.py(plot.y, t);
      scene.paths.push_back(line({f.x0 - 3, y}, {f.x0, y}, kInk, 1.0));
    }
  }

  for (const PlotSeries& s : plot.series) {
    std::vector<Point2> pixels;
    pixels.reserve(s.points.size());
    for (const Point2& p : s.points) pixels.emplace_back(f.px(plot.x, p.x()), f.py(plot.y, p.y()));
    for (std::vector<Point2>& part : clip(pixels, f))
      scene.paths.push_back(Path{std::move(part), s.color, s.width, s.opacity, s.dashed});
  }

  scene.paths.push_back(Path{{{f.x0, f.y0}, {f.x1, f.y0}, {f.x1, f.y1}, {f.x0, f.y1}, {f.x0, f.y0}},
                             kInk,
                             1.0,
                             1.0,
                             false});
  scene.texts.push_back({plot.title, {0.5 * (f.x0 + f.x1), 28}, 17, Anchor::middle, false, kInk});
  scene.texts.push_back(
      {plot.x.label, {0.5 * (f.x0 + f.x1), plot.height - 18.0}, 15, Anchor::middle, false, kInk});
  scene.texts.push_back({plot.y.label, {24, 0.5 * (f.y0 + f.y1)}, 15, Anchor::middle, true, kInk});

  // The legend beside the frame, top aligned with it.
  const double lx = f.x1 + 22;
  double ly = f.y0 + 12;
  for (const LegendEntry& entry : plot.legend) {
    scene.paths.push_back(
        Path{{{lx, ly}, {lx + 30, ly}}, entry.color, entry.width, 1.0, entry.dashed});
    scene.texts.push_back({entry.label, {lx + 38, ly + 5}, 14, Anchor::start, false, kInk});
    ly += 24;
  }
  ly += 8;
  for (const std::string& note : plot.notes) {
    scene.texts.push_back({note, {lx, ly + 5}, 12, Anchor::start, false, kNote});
    ly += 18;
  }
  return scene;
}

}  // namespace animkit::plot
