#include "animkit/io/convergence_report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "animkit/cloth/integrator_registry.h"
#include "animkit/io/atomic_write.h"
#include "animkit/io/png.h"

namespace animkit {

namespace {

// Okabe and Ito's colour-blind-safe palette (yellow left out: it vanishes on white).
constexpr std::array<PlotColor, 7> kPalette{{{0, 114, 178},
                                             {213, 94, 0},
                                             {0, 158, 115},
                                             {204, 121, 167},
                                             {230, 159, 0},
                                             {86, 180, 233},
                                             {0, 0, 0}}};
constexpr PlotColor kToleranceColor{120, 120, 120};

// A time as a table shows it: three significant digits, no exponent.
std::string milliseconds(double ms) {
  char text[32];
  const int decimals = ms >= 100 ? 0 : ms >= 10 ? 1 : ms >= 1 ? 2 : 3;
  std::snprintf(text, sizeof text, "%.*f", decimals, ms);
  return text;
}

std::string general(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

}  // namespace

PlotColor integrator_color(std::string_view integrator) {
  const auto entries = cloth_integrators();
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (entries[i].name == integrator) return kPalette[i % kPalette.size()];
  }
  return kPalette.back();
}

LinePlot convergence_plot(const ConvergenceStudy& study, std::string_view title) {
  LinePlot plot;
  plot.title = std::string(title);
  // The x axis ends at the slowest solver's 90th-percentile step (nearest rank): a one-off
  // slow step (e.g. a first step that also factorizes) does not squeeze every other curve
  // into the left edge; the table keeps its time.
  double ms_end = 0.0, ms_max = 0.0, relative_max = 1.0;
  for (const SolverStudy& solver : study.solvers) {
    std::vector<double> ends;
    for (const StudyStep& step : solver.steps) {
      ends.push_back(step.curve.back().ms);
      for (const CurvePoint& p : step.curve)
        relative_max = std::max(relative_max, p.relative_gradient);
    }
    if (ends.empty()) continue;
    std::sort(ends.begin(), ends.end());
    const auto rank = static_cast<std::size_t>(std::ceil(0.9 * static_cast<double>(ends.size())));
    ms_end = std::max(ms_end, ends[rank - 1]);
    ms_max = std::max(ms_max, ends.back());
  }
  plot.x = {"wall time since the step began (ms)", 0.0, ms_end > 0.0 ? 1.02 * ms_end : 1.0, false};
  // Down to a decade below the tolerance: a last iteration that overshoots it further is
  // drawn on the floor. Up to 1, or the decade above the highest point.
  plot.y = {"relative gradient |grad g| / |grad g(y)|",
            std::pow(10.0, std::floor(std::log10(study.tolerance)) - 1.0),
            std::min(1e6, std::pow(10.0, std::ceil(std::log10(relative_max) - 1e-9))), true};

  const auto curve = [](const StudyStep& step) {
    std::vector<Point2> points;
    for (const CurvePoint& p : step.curve) points.emplace_back(p.ms, p.relative_gradient);
    return points;
  };
  for (const SolverStudy& solver : study.solvers) {
    for (const StudyStep& step : solver.steps)
      plot.series.push_back({curve(step), integrator_color(solver.integrator), 1.0, 0.35, false});
  }
  plot.series.push_back({{{plot.x.min, study.tolerance}, {plot.x.max, study.tolerance}},
                         kToleranceColor,
                         1.2,
                         1.0,
                         true});
  for (const SolverStudy& solver : study.solvers) {
    if (solver.steps.empty()) continue;
    const StudyStep& median = solver.steps[static_cast<std::size_t>(solver.summary.median_step)];
    plot.series.push_back({curve(median), integrator_color(solver.integrator), 2.6, 1.0, false});
    plot.legend.push_back(
        {solver.integrator + "  " + milliseconds(solver.summary.ms_median) + " ms",
         integrator_color(solver.integrator), 2.6, false});
  }
  plot.legend.push_back({"tolerance " + general(study.tolerance), kToleranceColor, 1.2, true});
  const std::size_t steps = study.solvers.empty() ? 0 : study.solvers.front().steps.size();
  plot.notes = {"thin: each of " + std::to_string(steps) + " steps", "bold: the median step",
                "legend: median ms per step"};
  if (ms_max > plot.x.max) plot.notes.push_back("slower steps cut at the right edge");
  return plot;
}

std::string convergence_table_markdown(const ConvergenceStudy& study) {
  std::string table =
      "| solver | median ms/step | max ms/step | median iterations/step | converged steps |\n"
      "|---|---:|---:|---:|---:|\n";
  for (const SolverStudy& solver : study.solvers) {
    const StudySummary& s = solver.summary;
    char converged[32];
    std::snprintf(converged, sizeof converged, "%.0f%%", 100.0 * s.converged_fraction);
    table += "| " + solver.integrator + " | " + milliseconds(s.ms_median) + " | " +
             milliseconds(s.ms_max) + " | " + general(s.iterations_median) + " | " + converged +
             " |\n";
  }
  return table;
}

std::string convergence_curves_csv(const ConvergenceStudy& study) {
  std::string csv = "solver,step,iteration,ms,relative_gradient\n";
  char line[160];
  for (const SolverStudy& solver : study.solvers) {
    for (std::size_t k = 0; k < solver.steps.size(); ++k) {
      const auto& curve = solver.steps[k].curve;
      for (std::size_t i = 0; i < curve.size(); ++i) {
        std::snprintf(line, sizeof line, ",%zu,%zu,%.9g,%.17g\n", k + 1, i, curve[i].ms,
                      curve[i].relative_gradient);
        csv += solver.integrator + line;
      }
    }
  }
  return csv;
}

std::string convergence_study_json(const ConvergenceStudy& study, std::string_view scene) {
  nlohmann::ordered_json solvers = nlohmann::ordered_json::array();
  for (const SolverStudy& solver : study.solvers) {
    nlohmann::ordered_json steps = nlohmann::ordered_json::array();
    for (const StudyStep& step : solver.steps) {
      nlohmann::ordered_json curve = nlohmann::ordered_json::array();
      for (const CurvePoint& p : step.curve) curve.push_back({p.ms, p.relative_gradient});
      steps.push_back({{"ms", step.ms},
                       {"iterations", step.iterations},
                       {"converged", step.converged},
                       {"relative_tolerance", step.relative_tolerance},
                       {"curve", std::move(curve)}});
    }
    const StudySummary& s = solver.summary;
    solvers.push_back({{"integrator", solver.integrator},
                       {"summary",
                        {{"ms_median", s.ms_median},
                         {"ms_max", s.ms_max},
                         {"iterations_median", s.iterations_median},
                         {"converged_fraction", s.converged_fraction},
                         {"median_step", s.median_step}}},
                       {"steps", std::move(steps)}});
  }
  const nlohmann::ordered_json j = {{"scene", std::string(scene)},
                                    {"dt", study.dt},
                                    {"tolerance", study.tolerance},
                                    {"solvers", std::move(solvers)}};
  return j.dump(1) + "\n";
}

Result<void> write_convergence_report(const std::filesystem::path& dir,
                                      const ConvergenceStudy& study, std::string_view title,
                                      std::string_view scene) {
  const LinePlot plot = convergence_plot(study, title);
  auto image = line_plot_image(plot);
  if (!image) return fail(image.error().message);
  if (auto ok = write_png(dir / "convergence.png", *image); !ok) return ok;
  if (auto ok = write_file_atomic(dir / "convergence.svg", line_plot_svg(plot)); !ok) return ok;
  if (auto ok = write_file_atomic(dir / "table.md", convergence_table_markdown(study)); !ok)
    return ok;
  if (auto ok = write_file_atomic(dir / "curves.csv", convergence_curves_csv(study)); !ok)
    return ok;
  return write_file_atomic(dir / "study.json", convergence_study_json(study, scene));
}

}  // namespace animkit
