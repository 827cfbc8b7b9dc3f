#include "plot_raster.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace animkit::plot {

namespace {

constexpr int kSamples = 4;  // per pixel along each axis
constexpr double kDashOn = 6.0, kDashOff = 4.0;

// An edge going down the picture (y0 < y1); `winding` +1 if the polygon runs that way.
struct Edge {
  double x0, y0, x1, y1;
  int winding;
};

struct Crossing {
  double x;
  int winding;
};

// The pieces of `points` the pen draws with a 6 on, 4 off dash pattern.
std::vector<std::vector<Point2>> dashes(const std::vector<Point2>& points) {
  std::vector<std::vector<Point2>> pieces;
  bool on = true;
  double left = kDashOn;  // pixels left in the current dash or gap
  pieces.push_back({points.front()});
  for (std::size_t i = 1; i < points.size(); ++i) {
    Point2 a = points[i - 1];
    const Point2 b = points[i];
    double length = (b - a).norm();
    while (length > left) {
      a += (b - a) * (left / length);
      length -= left;
      if (on) pieces.back().push_back(a);
      on = !on;
      left = on ? kDashOn : kDashOff;
      if (on) pieces.push_back({a});
    }
    left -= length;
    if (on) pieces.back().push_back(b);
  }
  std::erase_if(pieces, [](const std::vector<Point2>& p) { return p.size() < 2; });
  return pieces;
}

}  // namespace

Canvas::Canvas(int width, int height, PlotColor background)
    : image_(width, height), coverage_(static_cast<std::size_t>(width) * height, 0) {
  std::fill(image_.pixels.begin(), image_.pixels.end(),
            Pixel{background.r, background.g, background.b, 255});
}

void Canvas::fill(const std::vector<Polygon>& polygons, PlotColor color, double opacity) {
  std::vector<Edge> edges;
  double top = image_.height, bottom = 0;
  for (const Polygon& polygon : polygons) {
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Point2& a = polygon[i];
      const Point2& b = polygon[(i + 1) % polygon.size()];
      if (a.y() == b.y()) continue;  // horizontal edges cross no sample row
      edges.push_back(a.y() < b.y() ? Edge{a.x(), a.y(), b.x(), b.y(), 1}
                                    : Edge{b.x(), b.y(), a.x(), a.y(), -1});
      top = std::min(top, std::min(a.y(), b.y()));
      bottom = std::max(bottom, std::max(a.y(), b.y()));
    }
  }
  if (edges.empty()) return;
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.y0 < b.y0; });

  const int w = image_.width, h = image_.height;
  const int first_row = std::max(0, static_cast<int>(std::floor(top * kSamples)));
  const int end_row = std::min(h * kSamples, static_cast<int>(std::ceil(bottom * kSamples)));
  int min_x = w, max_x = -1;
  std::vector<const Edge*> active;
  std::vector<Crossing> crossings;
  std::size_t next = 0;
  for (int sy = first_row; sy < end_row; ++sy) {
    const double y = (sy + 0.5) / kSamples;
    while (next < edges.size() && edges[next].y0 <= y) active.push_back(&edges[next++]);
    std::erase_if(active, [y](const Edge* e) { return e->y1 <= y; });
    crossings.clear();
    for (const Edge* e : active) {
      if (e->y0 > y) continue;
      crossings.push_back({e->x0 + (y - e->y0) * (e->x1 - e->x0) / (e->y1 - e->y0), e->winding});
    }
    std::sort(crossings.begin(), crossings.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    std::uint16_t* row = coverage_.data() + static_cast<std::size_t>(sy / kSamples) * w;
    int winding = 0;
    for (std::size_t i = 0; i + 1 < crossings.size(); ++i) {
      winding += crossings[i].winding;
      if (winding == 0) continue;
      // Samples at (sx + 1/2) / kSamples inside [x_i, x_{i+1}).
      const auto sample = [](double x) { return static_cast<int>(std::ceil(x * kSamples - 0.5)); };
      const int begin = std::max(0, sample(crossings[i].x));
      const int end = std::min(w * kSamples, sample(crossings[i + 1].x));
      for (int sx = begin; sx < end; ++sx) ++row[sx / kSamples];
      if (begin < end) {
        min_x = std::min(min_x, begin / kSamples);
        max_x = std::max(max_x, (end - 1) / kSamples);
      }
    }
  }
  if (max_x < min_x) return;
  constexpr double kFull = kSamples * kSamples;
  for (int py = first_row / kSamples; py <= (end_row - 1) / kSamples; ++py) {
    for (int px = min_x; px <= max_x; ++px) {
      std::uint16_t& covered = coverage_[static_cast<std::size_t>(py) * w + px];
      if (covered == 0) continue;
      const double a = opacity * std::min(1.0, covered / kFull);
      covered = 0;
      Pixel& p = image_.at(px, py);
      const auto blend = [a](std::uint8_t under, std::uint8_t over) {
        return static_cast<std::uint8_t>(std::lround(under + a * (over - under)));
      };
      p = Pixel{blend(p.r, color.r), blend(p.g, color.g), blend(p.b, color.b), 255};
    }
  }
}

void Canvas::stroke(const std::vector<Point2>& points, PlotColor color, double width,
                    double opacity, bool dashed) {
  if (points.size() < 2) return;
  const std::vector<std::vector<Point2>> pieces =
      dashed ? dashes(points) : std::vector<std::vector<Point2>>{points};
  const double r = 0.5 * width;
  std::vector<Polygon> polygons;
  for (const std::vector<Point2>& piece : pieces) {
    for (std::size_t i = 1; i < piece.size(); ++i) {
      const Point2 a = piece[i - 1], b = piece[i];
      const double length = (b - a).norm();
      if (length < 1e-9) continue;
      // The normal turned the same way for every segment: every quad has the same winding.
      const Point2 n = Point2(-(b - a).y(), (b - a).x()) * (r / length);
      polygons.push_back({a - n, b - n, b + n, a + n});
    }
    // Round joints, wound like the quads, so wide lines do not crack at their bends.
    if (width < 1.5) continue;
    for (std::size_t i = 1; i + 1 < piece.size(); ++i) {
      Polygon disc;
      for (int k = 0; k < 8; ++k) {
        const double angle = k * std::numbers::pi / 4;
        disc.push_back(piece[i] + r * Point2(std::cos(angle), std::sin(angle)));
      }
      polygons.push_back(std::move(disc));
    }
  }
  fill(polygons, color, opacity);
}

}  // namespace animkit::plot
