#include "animkit/io/line_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "animkit/core/validation.h"
#include "plot_layout.h"
#include "plot_raster.h"
#include "xml_text.h"

namespace animkit {

namespace {

constexpr PlotColor kBackground{255, 255, 255};

std::optional<Error> validate_axis(const PlotAxis& axis, const char* name) {
  const std::string what = std::string(name) + " axis";
  if (!std::isfinite(axis.min) || !std::isfinite(axis.max) || !(axis.min < axis.max)) {
    return Error{what + " range must be finite with min < max, got " + format_number(axis.min) +
                 " .. " + format_number(axis.max)};
  }
  if (axis.log10 && axis.min <= 0.0) {
    return Error{what + " is logarithmic but its minimum " + format_number(axis.min) +
                 " is not positive"};
  }
  return std::nullopt;
}

std::string hex(PlotColor c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", c.r, c.g, c.b);
  return text;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  return text;
}

// The glyph outlines of `text` placed as the layout says (pixels, y down). Text strokes are
// in em units with the baseline at y = 0 and y up.
Result<std::vector<plot::Polygon>> text_polygons(const plot::Text& text, const TextOptions& font) {
  auto strokes = text_strokes(text.text, font);
  if (!strokes) return fail(strokes.error().message);
  double min_u = std::numeric_limits<double>::max(), max_u = std::numeric_limits<double>::lowest();
  for (const Stroke& stroke : *strokes) {
    for (const Point2& p : stroke) {
      min_u = std::min(min_u, p.x());
      max_u = std::max(max_u, p.x());
    }
  }
  const double shift = text.anchor == plot::Anchor::start    ? 0.0
                       : text.anchor == plot::Anchor::middle ? -0.5 * (min_u + max_u)
                                                             : -max_u;
  std::vector<plot::Polygon> polygons;
  for (const Stroke& stroke : *strokes) {
    plot::Polygon polygon;
    for (const Point2& p : stroke) {
      const double u = (p.x() + shift) * text.size, v = p.y() * text.size;
      polygon.push_back(text.vertical ? text.at + Point2(-v, -u) : text.at + Point2(u, -v));
    }
    polygons.push_back(std::move(polygon));
  }
  return polygons;
}

}  // namespace

std::optional<Error> LinePlot::validate() const {
  if (width < 320 || width > 4096 || height < 320 || height > 4096) {
    return Error{"plot size must be between 320 and 4096 pixels per side, got " +
                 std::to_string(width) + " x " + std::to_string(height)};
  }
  if (auto error = validate_axis(x, "x")) return error;
  if (auto error = validate_axis(y, "y")) return error;
  for (std::size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& s = series[i];
    const std::string what = "plot series " + std::to_string(i);
    if (!(s.width > 0.0 && s.width <= 100.0))
      return Error{what + " width must be in (0, 100] pixels, got " + format_number(s.width)};
    if (!(s.opacity > 0.0 && s.opacity <= 1.0))
      return Error{what + " opacity must be in (0, 1], got " + format_number(s.opacity)};
    for (const Point2& p : s.points) {
      if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
        return Error{what + " has a non-finite point"};
    }
  }
  return std::nullopt;
}

std::string line_plot_svg(const LinePlot& plot) {
  const plot::Scene scene = plot::layout(plot);
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                    std::to_string(scene.width) + "\" height=\"" + std::to_string(scene.height) +
                    "\" viewBox=\"0 0 " + std::to_string(scene.width) + " " +
                    std::to_string(scene.height) + "\">\n";
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"" + hex(kBackground) + "\"/>\n";
  svg += "<g fill=\"none\" stroke-linejoin=\"round\">\n";
  for (const plot::Path& path : scene.paths) {
    if (path.points.size() < 2) continue;
    svg +=
        "<polyline stroke=\"" + hex(path.color) + "\" stroke-width=\"" + number(path.width) + "\"";
    if (path.opacity < 1.0) svg += " stroke-opacity=\"" + number(path.opacity) + "\"";
    if (path.dashed) svg += " stroke-dasharray=\"6 4\"";
    svg += " points=\"";
    for (const Point2& p : path.points) svg += number(p.x()) + "," + number(p.y()) + " ";
    svg.back() = '"';
    svg += "/>\n";
  }
  svg += "</g>\n<g font-family=\"DejaVu Sans, sans-serif\">\n";
  for (const plot::Text& text : scene.texts) {
    if (text.text.empty()) continue;
    const char* anchor = text.anchor == plot::Anchor::start    ? "start"
                         : text.anchor == plot::Anchor::middle ? "middle"
                                                               : "end";
    const std::string x = number(text.at.x()), y = number(text.at.y());
    // Appended piece by piece: GCC 12 misreads chains of string + literal (-Wrestrict).
    for (const std::string& piece :
         {std::string("<text x=\""), x, std::string("\" y=\""), y, std::string("\" font-size=\""),
          number(text.size), std::string("\" text-anchor=\""), std::string(anchor),
          std::string("\" fill=\""), hex(text.color), std::string("\"")})
      svg += piece;
    if (text.vertical) {
      for (const std::string& piece :
           {std::string(" transform=\"rotate(-90 "), x, std::string(" "), y, std::string(")\"")})
        svg += piece;
    }
    svg += '>';
    svg += xml_text(text.text);
    svg += "</text>\n";
  }
  svg += "</g>\n</svg>\n";
  return svg;
}

Result<Image> line_plot_image(const LinePlot& plot, const TextOptions& font) {
  if (auto error = plot.validate()) return fail(error->message);
  const plot::Scene scene = plot::layout(plot);
  plot::Canvas canvas(scene.width, scene.height, kBackground);
  for (const plot::Path& path : scene.paths)
    canvas.stroke(path.points, path.color, path.width, path.opacity, path.dashed);
  for (const plot::Text& text : scene.texts) {
    // Blank text has no outline (text_strokes refuses it): nothing to draw.
    if (std::all_of(text.text.begin(), text.text.end(), [](char c) { return c == ' '; })) continue;
    auto polygons = text_polygons(text, font);
    if (!polygons) return fail(polygons.error().message);
    canvas.fill(*polygons, text.color, 1.0);
  }
  return canvas.image();
}

}  // namespace animkit
