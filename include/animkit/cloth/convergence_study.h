#pragma once
// The convergence study of the implicit integrators: every solver advances the same
// cloth from the same state for the same steps, recording after each of its iterations the
// gradient norm of the incremental potential relative to its value at the prediction y, and
// the wall time since the substep began. All of them stop on the same test (integrator_settings.h),
// so their curves and times compare one to one. The numbers only: the plot, the table and the
// files are written by io/convergence_report.h.
#include <functional>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/core/result.h"

namespace animkit {

/// What a convergence study runs: the step, how many steps, the tolerance and the solvers.
struct ConvergenceStudyOptions {
  double dt = 1.0 / 60.0;  ///< seconds per step (one substep each), in kTimeStepRange
  int steps = 10;          ///< steps per solver, in [1, kMaxStudySteps]
  /// Relative gradient every solver stops at (set on each one's registry defaults), in (0, 1).
  double tolerance = 1e-4;
  /// Registry names (integrator_registry.h) in the order to run and plot them; empty: every
  /// implicit integrator of the registry, in its order (so solvers added later join).
  std::vector<std::string> integrators;

  /// An Error naming the first invalid field (dt, steps, tolerance, an unknown, non-iterative
  /// or repeated integrator), or none.
  std::optional<Error> validate() const;
};

/// Steps per solver the study accepts: its curves are kept whole in memory.
constexpr int kMaxStudySteps = 10'000;

/// One point of a convergence curve.
struct CurvePoint {
  double ms = 0.0;                 ///< wall time since the substep began (ms), >= 0
  double relative_gradient = 1.0;  ///< |grad g(x)| / |grad g(y)|
};

/// One step of one solver in the study: its convergence curve, time and iterations.
struct StudyStep {
  /// (0 ms, 1) at the prediction, then one point per iteration of the solver.
  std::vector<CurvePoint> curve;
  double ms = 0.0;         ///< wall time of the whole step (ms), velocity update included
  int iterations = 0;      ///< iterations of the solver (Newton iterations, sweeps, ...)
  bool converged = false;  ///< the solver met its stopping test (StepReport::converged)
  /// The relative gradient the solver stopped at: the tolerance, or the rounding floor of the
  /// stopping test when that is higher (implicit_substep.h).
  double relative_tolerance = 0.0;
};

/// Aggregates of one solver's steps (summarize_study()); all zero for no steps.
struct StudySummary {
  double ms_median = 0.0;           ///< median of StudyStep::ms over the steps
  double ms_max = 0.0;              ///< longest StudyStep::ms over the steps
  double iterations_median = 0.0;   ///< median of StudyStep::iterations over the steps
  double converged_fraction = 0.0;  ///< steps that reached the tolerance, in [0, 1]
  int median_step = 0;              ///< index of a step whose time is the median (lower one)
};

/// One solver's part of the study.
struct SolverStudy {
  std::string integrator;        ///< registry name
  std::vector<StudyStep> steps;  ///< one per step, in order (ConvergenceStudyOptions::steps)
  StudySummary summary;          ///< summarize_study() of `steps`
};

/// The result of a convergence study: every solver's steps over the same cloth.
struct ConvergenceStudy {
  double dt = 0.0;         ///< seconds per step, from the options
  double tolerance = 0.0;  ///< the relative gradient every solver stopped at, from the options
  std::vector<SolverStudy> solvers;  ///< in the order of the options' integrators
};

/// Registry names of the integrators that iterate to a tolerance (all but explicit Euler).
std::vector<std::string> implicit_integrator_names();

/// Told after each step of each solver (registry name, steps done): for a progress line.
using StudyProgress = std::function<void(const std::string& integrator, int steps_done)>;

/// Runs the study. Errors: invalid options (an unknown or non-iterative integrator named,
/// one named twice, steps or tolerance out of range), a state that does not fit the model or
/// is not finite, and a solver whose state diverged (naming solver and step).
Result<ConvergenceStudy> run_convergence_study(const ClothModel& model, const ClothState& initial,
                                               const ConvergenceStudyOptions& options,
                                               const StudyProgress& progress = {});

/// The summary of some steps (what run_convergence_study fills in).
StudySummary summarize_study(const std::vector<StudyStep>& steps);

}  // namespace animkit
