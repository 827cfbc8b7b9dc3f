#include "animkit/trajectory/trajectory.h"

#include <algorithm>
#include <cmath>

#include "animkit/core/validation.h"

namespace animkit {

namespace {
constexpr double kMaxTravelPoints = 1e6;  // per pen-up move
}  // namespace

Trajectory Trajectory::all_pen_down(std::vector<Vec3> points) {
  Trajectory t;
  t.pen_down.assign(points.size(), 1);
  t.targets = std::move(points);
  return t;
}

Result<Strokes> fit_to_box(const Strokes& strokes, const DrawingBox& box,
                           const std::optional<Eigen::AlignedBox2d>& frame) {
  if (!std::isfinite(box.half_extent) || box.half_extent <= 0.0 || !std::isfinite(box.center_x) ||
      !std::isfinite(box.center_z)) {
    return fail("the drawing box must have a finite centre and a positive half extent, got " +
                format_number(box.half_extent));
  }
  Eigen::AlignedBox2d bounds;
  for (std::size_t s = 0; s < strokes.size(); ++s) {
    for (std::size_t i = 0; i < strokes[s].size(); ++i) {
      const Point2& p = strokes[s][i];
      if (!std::isfinite(p.x()) || !std::isfinite(p.y())) {
        return fail("stroke " + std::to_string(s) + " point " + std::to_string(i) +
                    " is not finite");
      }
      bounds.extend(p);
    }
  }
  if (bounds.isEmpty()) return fail("the drawing has no points");
  if (frame && !frame->isEmpty()) bounds = *frame;
  const double size = bounds.sizes().maxCoeff();
  if (!std::isfinite(size)) return fail("the drawing is too large to place (its size overflows)");
  // A single point (or all points equal) stays a point at the centre.
  const double scale = size > 0.0 ? 2.0 * box.half_extent / size : 0.0;
  // min + half the size, not (min + max) / 2: that sum overflows for a point at 1e308 (found
  // by fuzzing), while the size was just checked to be finite.
  const Point2 centre = bounds.min() + 0.5 * bounds.sizes();
  Strokes out;
  out.reserve(strokes.size());
  for (const Stroke& stroke : strokes) {
    Stroke placed;
    placed.reserve(stroke.size());
    for (const Point2& p : stroke) {
      const Point2 q = scale * (p - centre);
      placed.emplace_back(box.center_x + q.x(), box.center_z - q.y());
    }
    out.push_back(std::move(placed));
  }
  return out;
}

DrawingBox reachable_box(const Vec3& root, double reach, double plane_y, double fill) {
  const double height = root.y() - plane_y;
  const double radius = std::sqrt(std::max(0.0, reach * reach - height * height));
  return {root.x(), root.z(), fill * radius / std::sqrt(2.0)};
}

std::optional<Error> TravelOptions::validate() const {
  if (!std::isfinite(pen_lift) || pen_lift < 0.0) {
    return Error{"pen lift must be a finite number >= 0, got " + format_number(pen_lift)};
  }
  if (!std::isfinite(spacing) || spacing <= 0.0) {
    return Error{"travel spacing must be a positive finite number, got " + format_number(spacing)};
  }
  return std::nullopt;
}

Result<Trajectory> to_trajectory(const Strokes& plane_strokes, const TravelOptions& travel) {
  if (auto error = travel.validate()) return fail(error->message);
  Trajectory t;
  const auto add = [&](const Vec3& p, bool down) {
    t.targets.push_back(p);
    t.pen_down.push_back(down ? 1 : 0);
  };
  // Evenly spaced points from a to b, both excluded. Counted in double before the cast, so a
  // move across a huge box is refused rather than overflowing.
  bool too_long = false;
  const auto move = [&](const Vec3& a, const Vec3& b) {
    const double wanted = std::ceil((b - a).norm() / travel.spacing);
    if (!(wanted <= kMaxTravelPoints)) {
      too_long = true;
      return;
    }
    const int parts = std::max(1, static_cast<int>(wanted));
    for (int k = 1; k < parts; ++k) add(a + (b - a) * (static_cast<double>(k) / parts), false);
  };
  const Vec3 lift(0.0, travel.pen_lift, 0.0);
  bool first = true;
  Vec3 last = Vec3::Zero();
  for (const Stroke& stroke : plane_strokes) {
    if (stroke.empty()) continue;
    const Vec3 start(stroke.front().x(), 0.0, stroke.front().y());
    if (!first) {
      // Up, across, down: the pen leaves the paper before it moves.
      add(last + lift, false);
      move(last + lift, start + lift);
      add(start + lift, false);
    }
    for (const Point2& p : stroke) add(Vec3(p.x(), 0.0, p.y()), true);
    last = t.targets.back();
    first = false;
  }
  if (too_long) {
    return fail("a pen-up move is longer than " + format_number(kMaxTravelPoints) +
                " travel spacings");
  }
  if (t.targets.empty()) return fail("the drawing has no points");
  return t;
}

Strokes pen_down_strokes(const Trajectory& trajectory) {
  Strokes strokes;
  bool drawing = false;
  for (std::size_t i = 0; i < trajectory.targets.size(); ++i) {
    const bool down = i < trajectory.pen_down.size() ? trajectory.pen_down[i] != 0 : true;
    if (!down) {
      drawing = false;
      continue;
    }
    if (!drawing) strokes.emplace_back();
    strokes.back().emplace_back(trajectory.targets[i].x(), trajectory.targets[i].z());
    drawing = true;
  }
  return strokes;
}

}  // namespace animkit
