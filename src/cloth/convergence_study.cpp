#include "animkit/cloth/convergence_study.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <numeric>

#include "animkit/cloth/integrator.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/parameter_ranges.h"
#include "animkit/core/quote.h"
#include "animkit/core/validation.h"

namespace animkit {

namespace {

bool is_implicit(const IntegratorEntry& entry) {
  return tolerance_of(entry.defaults).has_value();
}

std::string implicit_names_text() {
  std::string names;
  for (const std::string& name : implicit_integrator_names())
    names += (names.empty() ? "" : ", ") + name;
  return names;
}

double median_of(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 == 1 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

// One step of `integrator` from `state`, timed, as a curve.
StudyStep study_step(ClothIntegrator& integrator, ClothState& state, double dt) {
  StepReport report;
  const auto start = std::chrono::steady_clock::now();
  integrator.step(state, dt, report, nullptr);
  StudyStep step;
  step.ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  step.iterations = report.newton_iterations;
  step.converged = report.converged;
  step.relative_tolerance = report.gradient_norm_start > 0.0
                                ? report.gradient_tolerance / report.gradient_norm_start
                                : 0.0;
  // Relative to the gradient at the prediction; a prediction that already solves the step
  // (zero gradient) has nothing to reduce.
  const double start_norm = report.gradient_norm_start;
  const auto relative = [start_norm](double norm) {
    return start_norm > 0.0 ? norm / start_norm : 0.0;
  };
  step.curve.reserve(report.iterations.size() + 1);
  step.curve.push_back({0.0, 1.0});
  for (const IterationRecord& record : report.iterations)
    step.curve.push_back({record.ms, relative(record.gradient_norm)});
  return step;
}

}  // namespace

std::optional<Error> ConvergenceStudyOptions::validate() const {
  if (!kTimeStepRange.contains(dt)) return Error{kTimeStepRange.refusal("time step (seconds)", dt)};
  if (steps < 1 || steps > kMaxStudySteps) {
    return Error{"steps must be between 1 and " + std::to_string(kMaxStudySteps) + ", got " +
                 std::to_string(steps)};
  }
  if (!std::isfinite(tolerance) || tolerance <= 0.0 || tolerance >= 1.0) {  // NaN: no ordering
    return Error{"tolerance must be between 0 and 1 (exclusive), got " + format_number(tolerance)};
  }
  for (std::size_t i = 0; i < integrators.size(); ++i) {
    const std::string& name = integrators[i];
    const IntegratorEntry* entry = find_integrator(name);
    if (!entry) {
      return Error{"unknown integrator " + quote_input(name) +
                   " (expected one of: " + implicit_names_text() + ")"};
    }
    if (!is_implicit(*entry)) {
      return Error{"integrator " + quote_input(name) +
                   " does not iterate to a tolerance, so it has no convergence curve (expected "
                   "one of: " +
                   implicit_names_text() + ")"};
    }
    if (std::find(integrators.begin(), integrators.begin() + static_cast<std::ptrdiff_t>(i),
                  name) != integrators.begin() + static_cast<std::ptrdiff_t>(i)) {
      return Error{"integrator " + quote_input(name) + " is named twice"};
    }
  }
  return std::nullopt;
}

std::vector<std::string> implicit_integrator_names() {
  std::vector<std::string> names;
  for (const IntegratorEntry& entry : cloth_integrators()) {
    if (is_implicit(entry)) names.emplace_back(entry.name);
  }
  return names;
}

StudySummary summarize_study(const std::vector<StudyStep>& steps) {
  StudySummary summary;
  if (steps.empty()) return summary;
  std::vector<double> ms, iterations;
  int converged = 0;
  for (const StudyStep& step : steps) {
    ms.push_back(step.ms);
    iterations.push_back(step.iterations);
    converged += step.converged ? 1 : 0;
  }
  summary.ms_median = median_of(ms);
  summary.ms_max = *std::max_element(ms.begin(), ms.end());
  summary.iterations_median = median_of(iterations);
  summary.converged_fraction = converged / static_cast<double>(steps.size());
  // The step at the lower median of the times: the curve a reader takes as typical.
  std::vector<int> order(steps.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return steps[static_cast<std::size_t>(a)].ms < steps[static_cast<std::size_t>(b)].ms;
  });
  summary.median_step = order[(order.size() - 1) / 2];
  return summary;
}

Result<ConvergenceStudy> run_convergence_study(const ClothModel& model, const ClothState& initial,
                                               const ConvergenceStudyOptions& options,
                                               const StudyProgress& progress) {
  if (auto error = options.validate()) return fail(error->message);
  const Eigen::Index size = 3 * static_cast<Eigen::Index>(model.particle_count());
  if (initial.positions.size() != size || initial.velocities.size() != size) {
    return fail("the initial state has " + std::to_string(initial.positions.size() / 3) +
                " particles but the cloth has " + std::to_string(model.particle_count()));
  }
  if (!all_finite(initial.positions) || !all_finite(initial.velocities))
    return fail("the initial state has a non-finite position or velocity");

  // Every solver's integrator shares one copy of the model.
  const auto shared_model = std::make_shared<const ClothModel>(model);
  ConvergenceStudy study;
  study.dt = options.dt;
  study.tolerance = options.tolerance;
  const std::vector<std::string> names =
      options.integrators.empty() ? implicit_integrator_names() : options.integrators;
  for (const std::string& name : names) {
    IntegratorSettings settings = find_integrator(name)->defaults;
    set_tolerance(settings, options.tolerance);
    set_record_iterations(settings, true);
    if (auto error = validate(settings)) return fail(name + ": " + error->message);
    const std::unique_ptr<ClothIntegrator> integrator = make_integrator(shared_model, settings);
    ClothState state = initial;
    SolverStudy solver{name, {}, {}};
    solver.steps.reserve(static_cast<std::size_t>(options.steps));
    for (int k = 0; k < options.steps; ++k) {
      solver.steps.push_back(study_step(*integrator, state, options.dt));
      const StudyStep& step = solver.steps.back();
      const bool finite_curve =
          std::all_of(step.curve.begin(), step.curve.end(),
                      [](const CurvePoint& p) { return std::isfinite(p.relative_gradient); });
      if (!all_finite(state.positions) || !all_finite(state.velocities) || !finite_curve) {
        return fail(name + " diverged in step " + std::to_string(k + 1) +
                    " (a non-finite position, velocity or gradient)");
      }
      if (progress) progress(name, k + 1);
    }
    solver.summary = summarize_study(solver.steps);
    study.solvers.push_back(std::move(solver));
  }
  return study;
}

}  // namespace animkit
