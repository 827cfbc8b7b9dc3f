#pragma once
// The files of a convergence study (`animkit cloth-study --out DIR`): the plot of the relative
// gradient against wall time (convergence.png, convergence.svg), the summary table
// (table.md), the raw curves (curves.csv) and everything in one study.json.
#include <filesystem>
#include <string>
#include <string_view>

#include "animkit/cloth/convergence_study.h"
#include "animkit/io/line_plot.h"

namespace animkit {

/// One colour per integrator, fixed by its place in the registry, so a solver has the same
/// colour in every study.
PlotColor integrator_color(std::string_view integrator);

/// The plot: log10 relative gradient (from a decade below the tolerance up to 1, or higher if a
/// curve rises above 1) against ms since the substep began, up to the slowest solver's
/// 90th-percentile step (curves cut at the frame); each step's curve thin and translucent, the
/// median step's bold, the tolerance dashed, a legend with the median times.
LinePlot convergence_plot(const ConvergenceStudy& study, std::string_view title);

/// | solver | median ms/step | max ms/step | median iterations/step | converged steps |,
/// one row per solver, in the study's order.
std::string convergence_table_markdown(const ConvergenceStudy& study);

/// solver,step,iteration,ms,relative_gradient: one row per curve point (iteration 0 is the
/// prediction, at 0 ms and 1); steps count from 1.
std::string convergence_curves_csv(const ConvergenceStudy& study);

/// {"scene", "dt", "tolerance", "solvers": [{"integrator", "summary": {"ms_median", "ms_max",
/// "iterations_median", "converged_fraction", "median_step"}, "steps": [{"ms", "iterations",
/// "converged", "relative_tolerance", "curve": [[ms, relative_gradient], ...]}]}]}.
std::string convergence_study_json(const ConvergenceStudy& study, std::string_view scene);

/// Writes the five files into `dir` (which must exist), each atomically; `title` heads the
/// plot and `scene` names the scene in study.json. Errors: the font's, the file system's.
Result<void> write_convergence_report(const std::filesystem::path& dir,
                                      const ConvergenceStudy& study, std::string_view title,
                                      std::string_view scene);

}  // namespace animkit
