#include "animkit/io/reach_report.h"

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>

#include "animkit/io/atomic_write.h"
#include "animkit/io/line_plot.h"
#include "animkit/io/png.h"

namespace animkit {

namespace {

constexpr PlotColor kBefore{230, 120, 30}, kAfter{40, 90, 200}, kTarget{30, 150, 60};
constexpr double kCentimetresPerMetre = 100.0;
// The plot's frame inside each view: the picture less line_plot's margins (84 px left, 262 px
// right for the legend, 48 px above, 64 px below; src/io/plot_layout.cpp).
constexpr double kReachFrameWidth = kReachViewWidth - 84.0 - 262.0;
constexpr double kReachFrameHeight = kReachPictureHeight - 48.0 - 64.0;

// A view: which world axis runs to the right (0 x, 2 z); y is always up.
struct View {
  const char* title;
  const char* axis_label;
  int right;
};

Point2 project(const Vec3& p, const View& view) {
  return Point2(p[view.right], p.y());
}

void add_bones(LinePlot& plot, const Skeleton& skeleton, const SkeletonPose& pose, const View& view,
               PlotColor color, double width) {
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    const int parent = skeleton.parents()[static_cast<std::size_t>(j)];
    if (parent < 0) continue;
    plot.series.push_back(
        PlotSeries{{project(pose.global_positions[static_cast<std::size_t>(parent)], view),
                    project(pose.global_positions[static_cast<std::size_t>(j)], view)},
                   color,
                   width,
                   1.0,
                   false});
  }
}

// A cross (or, small, a dot) of half-size `r` at `p`.
void add_mark(LinePlot& plot, const Point2& p, double r, PlotColor color, double width) {
  plot.series.push_back(PlotSeries{{p - Point2(r, r), p + Point2(r, r)}, color, width, 1.0, false});
  plot.series.push_back(
      PlotSeries{{p - Point2(r, -r), p + Point2(r, -r)}, color, width, 1.0, false});
}

LinePlot view_plot(const Skeleton& skeleton, const SkeletonPose& before, const SkeletonPose& after,
                   const Vec3& target, std::span<const int> feet, const View& view) {
  // One scale in metres per pixel for both axes and both views (so bones keep their lengths
  // and the views line up): the box around everything drawn, fitted to the frame.
  Vec3 lo = target, hi = target;
  for (const SkeletonPose* pose : {&before, &after}) {
    for (const Vec3& p : pose->global_positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  }
  const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(0.1));
  const double per_pixel = 1.1 * std::max(std::max(extent.x(), extent.z()) / kReachFrameWidth,
                                          extent.y() / kReachFrameHeight);
  const Vec3 mid = 0.5 * (lo + hi);
  LinePlot plot;
  plot.title = view.title;
  plot.width = kReachViewWidth;
  plot.height = kReachPictureHeight;
  const double half_x = 0.5 * per_pixel * kReachFrameWidth;
  const double half_y = 0.5 * per_pixel * kReachFrameHeight;
  plot.x = {view.axis_label, mid[view.right] - half_x, mid[view.right] + half_x, false};
  plot.y = {"Y (m)", mid.y() - half_y, mid.y() + half_y, false};
  const double half = std::max(half_x, half_y);
  add_bones(plot, skeleton, before, view, kBefore, 2.0);
  add_bones(plot, skeleton, after, view, kAfter, 3.0);
  const double r = 0.02 * half;
  add_mark(plot, project(target, view), 2 * r, kTarget, 3.0);
  for (int foot : feet) {
    add_mark(plot, project(before.global_positions[static_cast<std::size_t>(foot)], view), r,
             kBefore, 2.0);
    add_mark(plot, project(after.global_positions[static_cast<std::size_t>(foot)], view), 0.6 * r,
             kAfter, 2.0);
  }
  plot.legend = {{"before", kBefore, 2.0, false},
                 {"after", kAfter, 3.0, false},
                 {"target", kTarget, 3.0, false}};
  plot.notes = {"small crosses: the feet"};
  return plot;
}

}  // namespace

std::string reach_metrics_json(const ReachLabel& label, const HandReachResult& result) {
  nlohmann::ordered_json j = {
      {"input", label.input},
      {"frame", label.frame},
      {"hand", label.hand},
      {"target_m", {label.target.x(), label.target.y(), label.target.z()}},
      {"solver", label.solver},
      {"limits", label.limits},
      {"scale", label.scale},
      {"hand_error_cm", result.hand_error * kCentimetresPerMetre},
      {"foot_drift_cm", result.foot_drift * kCentimetresPerMetre},
      {"root_drift_cm", result.root_drift * kCentimetresPerMetre},
      {"iterations", result.ik.iterations},
      {"converged", result.ik.converged},
      {"reachable", result.ik.reachable},
      {"reached", result.reached},
      {"solve_ms", result.solve_ms},
  };
  // Names come from the user: bytes that are not UTF-8 become U+FFFD.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

Result<Image> reach_picture(const Skeleton& skeleton, const SkeletonPose& before,
                            const SkeletonPose& after, const Vec3& target,
                            std::span<const int> feet) {
  const std::array<View, 2> views{View{"Front: before and after the reach", "X (m)", 0},
                                  View{"Side", "Z (m)", 2}};
  Image both(2 * kReachViewWidth, kReachPictureHeight);
  for (std::size_t v = 0; v < views.size(); ++v) {
    auto image = line_plot_image(view_plot(skeleton, before, after, target, feet, views[v]));
    if (!image) return fail(image.error().message);
    for (int y = 0; y < image->height; ++y) {
      std::copy_n(image->pixels.begin() + static_cast<std::ptrdiff_t>(y) * image->width,
                  image->width,
                  both.pixels.begin() + static_cast<std::ptrdiff_t>(y) * both.width +
                      static_cast<std::ptrdiff_t>(v) * kReachViewWidth);
    }
  }
  return both;
}

Result<void> write_reach_report(const std::filesystem::path& dir, const ReachLabel& label,
                                const HandReachResult& result, const Skeleton& skeleton,
                                const SkeletonPose& before, const SkeletonPose& after,
                                std::span<const int> feet) {
  auto image = reach_picture(skeleton, before, after, label.target, feet);
  if (!image) return fail(image.error().message);
  if (auto ok = write_png(dir / "reach.png", *image); !ok) return ok;
  return write_file_atomic(dir / "metrics.json", reach_metrics_json(label, result));
}

}  // namespace animkit
