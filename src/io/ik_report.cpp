#include "animkit/io/ik_report.h"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>

#include "animkit/io/atomic_write.h"
#include "xml_text.h"

namespace animkit {

std::string ik_metrics_json(const IkRunLabel& label, const DrawingOptions& options,
                            const DrawingSummary& s) {
  nlohmann::ordered_json j = {
      {"solver", label.solver},
      {"shape", label.shape},
      {"targets", s.targets},
      {"converged_fraction", s.converged_fraction},
      {"unreachable_targets", s.unreachable_targets},
      {"iterations",
       {{"mean", s.iterations_mean}, {"median", s.iterations_median}, {"max", s.iterations_max}}},
      {"error", {{"mean", s.error_mean}, {"max", s.error_max}}},
      {"max_joint_step_rad", s.max_joint_step_rad},
      {"solve_time_us", {{"median", s.solve_time_us_median}, {"mean", s.solve_time_us_mean}}},
      {"options",
       {{"max_iterations", options.ik.max_iterations},
        {"tolerance", options.ik.tolerance},
        {"fabrik_rotations", to_string(options.ik.fabrik_rotations)},
        {"laps", options.laps},
        {"warm_start", options.warm_start}}},
  };
  if (label.limits) {
    // The arm ran as a skeleton through the tree solvers: the chain's FABRIK option is not used.
    j["options"].erase("fabrik_rotations");
    j["limits"] = *label.limits;
  }
  if (label.drawing) {
    const auto spacing = [](const SpacingStats& st) {
      return nlohmann::ordered_json{
          {"mean", st.mean}, {"cv", st.cv}, {"min", st.min}, {"max", st.max}};
    };
    j["drawing"] = {{"strokes", label.drawing->strokes},
                    {"pen_up_targets", label.drawing->pen_up_targets},
                    {"spacing_before", spacing(label.drawing->spacing_before)},
                    {"spacing_after", spacing(label.drawing->spacing_after)}};
  }
  // Names come from users (a file name may hold any bytes): bytes that are not UTF-8 are
  // written as U+FFFD rather than throwing, so the reports are always written.
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

std::string ik_path_csv(const DrawingRun& run) {
  std::string out =
      "frame,target_x,target_y,target_z,end_x,end_y,end_z,iterations,error,converged,reachable,"
      "pen_down\n";
  char line[512];
  for (std::size_t i = 0; i < run.frames.size(); ++i) {
    const DrawingFrame& f = run.frames[i];
    std::snprintf(line, sizeof line, "%zu,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%.17g,%d,%d,%d\n",
                  i, f.target.x(), f.target.y(), f.target.z(), f.end_effector.x(),
                  f.end_effector.y(), f.end_effector.z(), f.ik.iterations, f.ik.error,
                  f.ik.converged ? 1 : 0, f.ik.reachable ? 1 : 0, f.pen_down ? 1 : 0);
    out += line;
  }
  return out;
}

namespace {

// Maps the plane's (x, z) into SVG pixels with a uniform scale that fits every point.
struct TopViewFrame {
  double min_x = std::numeric_limits<double>::max(), min_z = min_x;
  double max_x = std::numeric_limits<double>::lowest(), max_z = max_x;
  double scale = 1.0, left = 0.0, top = 0.0;

  void include(const Vec3& p) {
    min_x = std::min(min_x, p.x());
    max_x = std::max(max_x, p.x());
    min_z = std::min(min_z, p.z());
    max_z = std::max(max_z, p.z());
  }
  void fit(double size, double margin, double title_height) {
    const double span = std::max({max_x - min_x, max_z - min_z, 1e-6});
    scale = (size - 2.0 * margin) / span;
    left = margin + 0.5 * (size - 2.0 * margin - (max_x - min_x) * scale);
    top = title_height + margin + 0.5 * (size - 2.0 * margin - (max_z - min_z) * scale);
  }
  double px(const Vec3& p) const { return left + (p.x() - min_x) * scale; }
  double py(const Vec3& p) const { return top + (p.z() - min_z) * scale; }
};

}  // namespace

std::string ik_drawing_svg(const IkRunLabel& label, const DrawingRun& run) {
  constexpr double size = 600.0, margin = 30.0, title_height = 66.0;
  TopViewFrame view;
  for (const DrawingFrame& f : run.frames) {
    view.include(f.target);
    view.include(f.end_effector);
  }
  view.fit(size, margin, title_height);

  const DrawingSummary s = summarize(run);
  char numbers[256];
  std::snprintf(numbers, sizeof numbers,
                "%d targets, %.1f%% converged, %.2f iterations per target, max joint step %.4f rad",
                s.targets, 100.0 * s.converged_fraction, s.iterations_mean, s.max_joint_step_rad);
  std::ostringstream svg;
  svg.precision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << size << "\" height=\""
      << size + title_height << "\" viewBox=\"0 0 " << size << ' ' << size + title_height << "\">\n"
      << "<title>" << xml_text(label.shape) << " drawn with " << xml_text(label.solver)
      << "</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << margin << "\" y=\"28\" font-family=\"sans-serif\" font-size=\"20\">"
      << xml_text(label.shape) << " \xE2\x80\x94 " << xml_text(label.solver) << "</text>\n"
      << "<text font-family=\"sans-serif\" font-size=\"12\" fill=\"#555\">"
      << "<tspan x=\"" << margin << "\" y=\"46\">top view of the plane y = 0 (x right, z down): "
      << "targets green, drawn path red</tspan>"
      << "<tspan x=\"" << margin << "\" y=\"62\">" << numbers << "</tspan></text>\n";

  // One lap of targets suffices: green where the pen draws, grey where it travels.
  for (const bool down : {true, false}) {
    svg << "<g fill=\"" << (down ? "#00cc00" : "#bbbbbb") << "\">\n";
    for (const DrawingFrame& f : run.frames) {
      if (f.lap != run.frames.back().lap || f.pen_down != down) continue;
      svg << "<circle cx=\"" << view.px(f.target) << "\" cy=\"" << view.py(f.target) << "\" r=\""
          << (down ? 2.5 : 1.5) << "\"/>\n";
    }
    svg << "</g>\n";
  }
  // One red polyline per stroke: pen-up travel and the reset between laps are not drawn.
  for (const auto& stroke : drawn_strokes(run.frames)) {
    svg << "<polyline fill=\"none\" stroke=\"#e00000\" stroke-width=\"1.5\" points=\"";
    for (const Vec3& e : stroke) svg << view.px(e) << ',' << view.py(e) << ' ';
    svg << "\"/>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

Result<void> write_ik_reports(const std::filesystem::path& dir, const IkRunLabel& label,
                              const DrawingOptions& options, const DrawingRun& run) {
  if (auto ok = ensure_output_directory(dir); !ok) return ok;
  if (auto ok =
          write_file_atomic(dir / "metrics.json", ik_metrics_json(label, options, summarize(run)));
      !ok) {
    return ok;
  }
  if (auto ok = write_file_atomic(dir / "path.csv", ik_path_csv(run)); !ok) return ok;
  return write_file_atomic(dir / "drawing.svg", ik_drawing_svg(label, run));
}

}  // namespace animkit
