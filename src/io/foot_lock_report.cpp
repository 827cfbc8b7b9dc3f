#include "animkit/io/foot_lock_report.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "animkit/io/atomic_write.h"
#include "animkit/io/line_plot.h"
#include "animkit/io/png.h"

namespace animkit {

namespace {

constexpr PlotColor kBefore{230, 120, 30}, kAfter{40, 90, 200}, kPlanted{30, 150, 60};
constexpr double kCentimetresPerMetre = 100.0;

const Vec3& ankle(const std::vector<Vec3>& trail, int f, int leg) {
  return trail[static_cast<std::size_t>(f) * 2 + leg];
}

// Top view: X against Z (metres), both feet (the right one dashed), planted spans of the
// result drawn bold.
LinePlot trail_plot(const FootLockResult& r, int frames) {
  LinePlot plot;
  plot.title = "Ankle trails from above: before and after foot locking";
  plot.x = {"Z (m)", 0, 1, false};
  plot.y = {"X (m)", 0, 1, false};
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (const auto* trail : {&r.ankles_before, &r.ankles_after}) {
    for (int leg = 0; leg < 2; ++leg) {
      PlotSeries s{{}, trail == &r.ankles_before ? kBefore : kAfter, 1.2, 1.0, leg == 1};
      for (int f = 0; f < frames; ++f) {
        const Vec3& a = ankle(*trail, f, leg);
        s.points.emplace_back(a.z(), a.x());
        lo[0] = std::min(lo[0], a.z()), hi[0] = std::max(hi[0], a.z());
        lo[1] = std::min(lo[1], a.x()), hi[1] = std::max(hi[1], a.x());
      }
      plot.series.push_back(std::move(s));
    }
  }
  for (int leg = 0; leg < 2; ++leg) {
    for (const FootContactSpan& span : r.contacts[leg].spans) {
      PlotSeries s{{}, kPlanted, 4.0, 0.8, false};
      for (int f = span.first; f <= span.last; ++f) {
        const Vec3& a = ankle(r.ankles_after, f, leg);
        s.points.emplace_back(a.z(), a.x());
      }
      plot.series.push_back(std::move(s));
    }
  }
  const double margin = 0.05 * std::max({hi[0] - lo[0], hi[1] - lo[1], 0.1});
  plot.x.min = lo[0] - margin, plot.x.max = hi[0] + margin;
  plot.y.min = lo[1] - margin, plot.y.max = hi[1] + margin;
  plot.legend = {{"before", kBefore, 2.0, false},
                 {"after", kAfter, 2.0, false},
                 {"planted (after)", kPlanted, 4.0, false}};
  plot.notes = {"solid: left foot, dashed: right foot"};
  return plot;
}

// Horizontal ankle motion per frame (cm) on planted frames; other frames are left out (NaN
// would trip the plot's validation, so each span is its own series).
LinePlot sliding_plot(const FootLockResult& r, int frames) {
  LinePlot plot;
  plot.title = "Planted feet: horizontal motion per frame (cm)";
  plot.x = {"frame", 0, static_cast<double>(std::max(frames - 1, 1)), false};
  plot.y = {"cm per frame", 0, 0.5, false};
  double top = 0.0;
  for (const auto* trail : {&r.ankles_before, &r.ankles_after}) {
    for (int leg = 0; leg < 2; ++leg) {
      for (const FootContactSpan& span : r.contacts[leg].spans) {
        PlotSeries s{{}, trail == &r.ankles_before ? kBefore : kAfter, 1.5, 1.0, leg == 1};
        for (int f = span.first + 1; f <= span.last; ++f) {
          const Vec3 d = ankle(*trail, f, leg) - ankle(*trail, f - 1, leg);
          const double cm = std::hypot(d.x(), d.z()) * kCentimetresPerMetre;
          top = std::max(top, cm);
          s.points.emplace_back(f, cm);
        }
        if (s.points.size() >= 2) plot.series.push_back(std::move(s));
      }
    }
  }
  plot.y.max = std::max(0.5, 1.1 * top);
  plot.legend = {{"before", kBefore, 2.0, false}, {"after", kAfter, 2.0, false}};
  plot.notes = {"solid: left foot, dashed: right foot"};
  return plot;
}

}  // namespace

std::string foot_lock_metrics_json(const FootLockResult& result, const FootLockSettings& s,
                                   const FootLockClip& clip) {
  const FootLockMetrics& m = result.metrics;
  const auto pair = [](int left, int right) {
    return nlohmann::ordered_json{{"left", left}, {"right", right}};
  };
  nlohmann::ordered_json j = {
      {"input", clip.input},
      {"frames", clip.frames},
      {"frame_time", clip.frame_time},
      {"scale",
       {{"metres_per_unit", clip.metres_per_unit}, {"description", clip.scale_description}}},
      {"contacts", pair(m.contacts[0], m.contacts[1])},
      {"planted_frames", pair(m.planted_frames[0], m.planted_frames[1])},
      {"sliding_cm_per_frame",
       {{"before", {{"mean", m.slide_before_mean_cm}, {"max", m.slide_before_max_cm}}},
        {"after", {{"mean", m.slide_after_mean_cm}, {"max", m.slide_after_max_cm}}}}},
      {"ik_error_cm", {{"mean", m.ik_error_mean_cm}, {"max", m.ik_error_max_cm}}},
      {"max_joint_step_cm",
       {{"before", m.max_joint_step_before_cm}, {"after", m.max_joint_step_after_cm}}},
      {"max_leg_step_cm",
       {{"before", m.max_leg_step_before_cm}, {"after", m.max_leg_step_after_cm}}},
      {"max_correction_step_cm", m.max_correction_step_cm},
      {"ms_per_frame", m.ms_per_frame},
      {"settings",
       {{"height_threshold_m", s.height_threshold},
        {"speed_threshold_m_per_s", s.speed_threshold},
        {"min_contact_frames", s.min_contact_frames},
        {"merge_gap_frames", s.merge_gap_frames},
        {"blend_frames", s.blend_frames},
        {"knee_flexion_rad", {{"min", s.min_knee_flexion}, {"max", s.max_knee_flexion}}},
        {"knee_pole", std::string(to_string(s.knee_pole))},
        {"soft_reach_m", s.soft_reach}}},
  };
  // The input's name comes from the user: bytes that are not UTF-8 become U+FFFD.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

Result<Image> foot_lock_compare_image(const FootLockResult& result, int frames) {
  Image both(kFootLockPlotWidth, 2 * kFootLockPlotHeight);
  int row = 0;
  for (const LinePlot& plot : {trail_plot(result, frames), sliding_plot(result, frames)}) {
    auto image = line_plot_image(plot);
    if (!image) return fail(image.error().message);
    std::copy(image->pixels.begin(), image->pixels.end(),
              both.pixels.begin() + static_cast<std::ptrdiff_t>(row) * kFootLockPlotWidth);
    row += image->height;
  }
  return both;
}

Result<void> write_foot_lock_report(const std::filesystem::path& dir, const FootLockResult& result,
                                    const FootLockSettings& settings, const FootLockClip& clip) {
  auto image = foot_lock_compare_image(result, clip.frames);
  if (!image) return fail(image.error().message);
  if (auto ok = write_png(dir / "compare.png", *image); !ok) return ok;
  return write_file_atomic(dir / "metrics.json", foot_lock_metrics_json(result, settings, clip));
}

}  // namespace animkit
