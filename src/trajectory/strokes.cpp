#include "animkit/trajectory/strokes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include "animkit/core/validation.h"

namespace animkit {

namespace {

// Most points one piece between corners is cut into (see resample()).
constexpr double kMaxPiecePoints = 1e7;

// The stroke without consecutive duplicates (zero-length segments have no direction).
Stroke distinct_points(const Stroke& stroke) {
  Stroke out;
  out.reserve(stroke.size());
  for (const Point2& p : stroke) {
    if (out.empty() || (p - out.back()).norm() > 1e-12) out.push_back(p);
  }
  return out;
}

bool is_closed(const Stroke& s) {
  return s.size() > 2 && (s.front() - s.back()).norm() <= 1e-12;
}

// Turning angle at s[i] between s[i-1] -> s[i] and s[i] -> s[i+1].
double turn(const Point2& a, const Point2& b, const Point2& c) {
  const Point2 u = (b - a).normalized(), v = (c - b).normalized();
  return std::atan2(u.x() * v.y() - u.y() * v.x(), u.dot(v));
}

// Appends points cutting a..b (polyline s[first..last]) into equal parts of at most
// `spacing`, excluding s[first] (already in `out`), including s[last].
void resample_piece(const Stroke& s, std::size_t first, std::size_t last, double spacing,
                    Stroke& out) {
  double length = 0.0;
  for (std::size_t i = first; i < last; ++i) length += (s[i + 1] - s[i]).norm();
  // Counted in double and capped before the cast: a tiny spacing must not overflow an int.
  const double wanted = std::ceil(length / spacing - 1e-9);
  const int parts = static_cast<int>(std::clamp(wanted, 1.0, kMaxPiecePoints));
  const double step = length / parts;
  std::size_t i = first;
  double walked = 0.0;  // arc length at s[i]
  for (int k = 1; k < parts; ++k) {
    const double at = k * step;
    while (i + 1 < last && walked + (s[i + 1] - s[i]).norm() < at) {
      walked += (s[i + 1] - s[i]).norm();
      ++i;
    }
    const double segment = (s[i + 1] - s[i]).norm();
    const double t = segment > 0.0 ? std::clamp((at - walked) / segment, 0.0, 1.0) : 0.0;
    out.push_back(s[i] + t * (s[i + 1] - s[i]));
  }
  out.push_back(s[last]);
}

}  // namespace

double stroke_length(const Stroke& stroke) {
  double length = 0.0;
  for (std::size_t i = 1; i < stroke.size(); ++i) length += (stroke[i] - stroke[i - 1]).norm();
  return length;
}

SpacingStats spacing_stats(const Strokes& strokes) {
  SpacingStats stats;
  double sum = 0.0, sum_sq = 0.0;
  stats.min = std::numeric_limits<double>::infinity();
  for (const Stroke& s : strokes) {
    for (std::size_t i = 1; i < s.size(); ++i) {
      const double d = (s[i] - s[i - 1]).norm();
      sum += d;
      sum_sq += d * d;
      stats.min = std::min(stats.min, d);
      stats.max = std::max(stats.max, d);
      ++stats.segments;
    }
  }
  if (stats.segments == 0) {
    stats.min = 0.0;
    return stats;
  }
  stats.mean = sum / stats.segments;
  const double variance = std::max(0.0, sum_sq / stats.segments - stats.mean * stats.mean);
  stats.cv = stats.mean > 0.0 ? std::sqrt(variance) / stats.mean : 0.0;
  return stats;
}

std::optional<Error> ResampleOptions::validate() const {
  if (!std::isfinite(spacing) || spacing <= 0.0) {
    return Error{"spacing must be a positive finite number, got " + format_number(spacing)};
  }
  if (!std::isfinite(corner_angle) || corner_angle <= 0.0 || corner_angle > std::numbers::pi) {
    return Error{"corner angle must be in (0, pi] radians, got " + format_number(corner_angle)};
  }
  return std::nullopt;
}

std::vector<std::size_t> find_corners(const Stroke& stroke, double corner_angle, double scale) {
  std::vector<std::size_t> corners;
  const std::size_t n = stroke.size();
  if (n < 3) return corners;
  const bool closed = is_closed(stroke);
  // Closed strokes are walked round their n - 1 distinct points.
  const std::size_t ring = closed ? n - 1 : n;
  const auto step = [&](std::size_t i, int direction) -> std::optional<std::size_t> {
    if (closed) return (i + ring + static_cast<std::size_t>(direction + ring)) % ring;
    if (direction < 0) return i == 0 ? std::nullopt : std::optional(i - 1);
    return i + 1 >= n ? std::nullopt : std::optional(i + 1);
  };
  // The point at least `scale` of arc away (or the last one there is), walking one way.
  const auto reach = [&](std::size_t i, int direction) -> std::optional<std::size_t> {
    std::size_t j = i;
    double walked = 0.0;
    for (std::size_t k = 0; k + 1 < ring; ++k) {
      const auto next = step(j, direction);
      if (!next) break;
      walked += (stroke[*next] - stroke[j]).norm();
      j = *next;
      if (walked >= scale) break;
    }
    return j == i ? std::nullopt : std::optional(j);
  };
  std::vector<double> angle(ring, 0.0);
  for (std::size_t i = closed ? 0 : 1; i + (closed ? 0 : 1) < ring; ++i) {
    const auto back = reach(i, -1), ahead = reach(i, +1);
    if (back && ahead) angle[i] = std::abs(turn(stroke[*back], stroke[i], stroke[*ahead]));
  }
  // Corners of each bend, a bend being a run of consecutive points that turn at this scale:
  // its sharp vertices (turning by more than the angle between their own neighbours too: a
  // polygon's corners, however close together), or else, for a rounded bend, its sharpest
  // point.
  const auto local_turn = [&](std::size_t i) {
    const auto back = step(i, -1), ahead = step(i, +1);
    return back && ahead ? std::abs(turn(stroke[*back], stroke[i], stroke[*ahead])) : 0.0;
  };
  std::vector<char> done(ring, 0);
  for (std::size_t i = 0; i < ring; ++i) {
    if (angle[i] <= corner_angle || done[i]) continue;
    // Walk back to the start of the run (a closed stroke may wrap), then forward through it.
    std::size_t first = i;
    for (std::size_t k = 0; k + 1 < ring; ++k) {
      const auto previous = step(first, -1);
      if (!previous || angle[*previous] <= corner_angle || *previous == i) break;
      first = *previous;
    }
    std::size_t sharpest = first;
    bool any_vertex = false;
    for (std::size_t j = first, k = 0; k < ring; ++k) {
      done[j] = 1;
      if (angle[j] > angle[sharpest]) sharpest = j;
      if (local_turn(j) > corner_angle) {
        corners.push_back(j);
        any_vertex = true;
      }
      const auto next = step(j, +1);
      if (!next || angle[*next] <= corner_angle || done[*next]) break;
      j = *next;
    }
    if (!any_vertex) corners.push_back(sharpest);
  }
  std::sort(corners.begin(), corners.end());
  return corners;
}

Stroke resample(const Stroke& stroke, const ResampleOptions& options) {
  const Stroke s = distinct_points(stroke);
  if (s.size() < 2) return s;
  std::vector<std::size_t> keep = find_corners(s, options.corner_angle, options.spacing);
  if (keep.empty() || keep.front() != 0) keep.insert(keep.begin(), 0);
  keep.push_back(s.size() - 1);
  Stroke out{s.front()};
  for (std::size_t k = 0; k + 1 < keep.size(); ++k) {
    resample_piece(s, keep[k], keep[k + 1], options.spacing, out);
  }
  return out;
}

Strokes resample(const Strokes& strokes, const ResampleOptions& options) {
  Strokes out;
  out.reserve(strokes.size());
  for (const Stroke& s : strokes) out.push_back(resample(s, options));
  return out;
}

Stroke smooth(const Stroke& stroke, int radius, const std::vector<std::size_t>& fixed) {
  if (radius <= 0 || stroke.size() < 3) return stroke;
  const bool closed = is_closed(stroke);
  const std::size_t n = stroke.size();
  std::vector<char> pinned(n, 0);
  pinned.front() = pinned.back() = !closed;
  for (std::size_t i : fixed) {
    if (i < n) pinned[i] = 1;
  }
  Stroke out = stroke;
  // A closed stroke wraps around (its last point repeats the first); an open one shrinks the
  // window near its ends so they stay put.
  const std::size_t ring = closed ? n - 1 : n;
  for (std::size_t i = 0; i < ring; ++i) {
    if (pinned[i]) continue;
    Point2 sum = Point2::Zero();
    int count = 0;
    for (int d = -radius; d <= radius; ++d) {
      long j = static_cast<long>(i) + d;
      if (closed) {
        j = ((j % static_cast<long>(ring)) + static_cast<long>(ring)) % static_cast<long>(ring);
      } else if (j < 0 || j >= static_cast<long>(n)) {
        continue;
      }
      sum += stroke[static_cast<std::size_t>(j)];
      ++count;
    }
    out[i] = sum / count;
  }
  if (closed) out.back() = out.front();
  return out;
}

}  // namespace animkit
