#include "animkit/cloth/convergence_study.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"

namespace animkit {
namespace {

BuiltCloth small_cloth() {
  auto built = build_cloth(make_grid_cloth({.cells = 4}));
  EXPECT_TRUE(built.has_value());
  return std::move(*built);
}

ConvergenceStudyOptions options_with(std::vector<std::string> integrators, int steps = 3) {
  ConvergenceStudyOptions options;
  options.steps = steps;
  options.integrators = std::move(integrators);
  return options;
}

std::string error_of(const ConvergenceStudyOptions& options) {
  const BuiltCloth cloth = small_cloth();
  const auto study = run_convergence_study(cloth.model, cloth.state, options);
  return study ? std::string("no error") : study.error().message;
}

TEST(ConvergenceStudy, DefaultsToEveryImplicitIntegratorOfTheRegistry) {
  const std::vector<std::string> names = implicit_integrator_names();
  std::vector<std::string> expected;
  for (const IntegratorEntry& entry : cloth_integrators()) {
    if (tolerance_of(entry.defaults)) expected.emplace_back(entry.name);
  }
  EXPECT_EQ(names, expected);
  EXPECT_NE(std::find(names.begin(), names.end(), "implicit-pcg"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "explicit"), names.end());

  const BuiltCloth cloth = small_cloth();
  const auto study = run_convergence_study(cloth.model, cloth.state, options_with({}));
  ASSERT_TRUE(study.has_value()) << study.error().message;
  ASSERT_EQ(study->solvers.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) EXPECT_EQ(study->solvers[i].integrator, names[i]);
}

TEST(ConvergenceStudy, EveryCurveStartsAtOneAndRecordsEachIteration) {
  const BuiltCloth cloth = small_cloth();
  ConvergenceStudyOptions options = options_with({}, 4);
  options.tolerance = 1e-5;
  const auto study = run_convergence_study(cloth.model, cloth.state, options);
  ASSERT_TRUE(study.has_value()) << study.error().message;
  EXPECT_EQ(study->tolerance, 1e-5);
  for (const SolverStudy& solver : study->solvers) {
    ASSERT_EQ(solver.steps.size(), 4u) << solver.integrator;
    for (const StudyStep& step : solver.steps) {
      ASSERT_FALSE(step.curve.empty());
      EXPECT_EQ(step.curve.front().ms, 0.0);
      EXPECT_EQ(step.curve.front().relative_gradient, 1.0);
      EXPECT_EQ(step.curve.size(), static_cast<std::size_t>(step.iterations) + 1)
          << solver.integrator;
      EXPECT_GE(step.iterations, 1) << solver.integrator;
      for (std::size_t i = 1; i < step.curve.size(); ++i) {
        EXPECT_GE(step.curve[i].ms, step.curve[i - 1].ms) << solver.integrator;
        EXPECT_GE(step.curve[i].relative_gradient, 0.0);
      }
      EXPECT_LE(step.curve.back().ms, step.ms) << solver.integrator;
      EXPECT_TRUE(step.converged) << solver.integrator;
      EXPECT_GE(step.relative_tolerance, 1e-5 * (1 - 1e-12)) << solver.integrator;
      EXPECT_LE(step.curve.back().relative_gradient, step.relative_tolerance * (1 + 1e-12))
          << solver.integrator;
    }
  }
}

TEST(ConvergenceStudy, SummaryAgreesWithTheSteps) {
  const BuiltCloth cloth = small_cloth();
  const auto study = run_convergence_study(cloth.model, cloth.state, options_with({}, 5));
  ASSERT_TRUE(study.has_value()) << study.error().message;
  for (const SolverStudy& solver : study->solvers) {
    const StudySummary& s = solver.summary;
    std::vector<double> ms;
    for (const StudyStep& step : solver.steps) ms.push_back(step.ms);
    std::sort(ms.begin(), ms.end());
    EXPECT_EQ(s.ms_median, ms[2]) << solver.integrator;
    EXPECT_EQ(s.ms_max, ms.back());
    EXPECT_EQ(solver.steps[static_cast<std::size_t>(s.median_step)].ms, s.ms_median);
    EXPECT_EQ(s.converged_fraction, 1.0);
    EXPECT_GE(s.iterations_median, 1.0);
  }
}

TEST(ConvergenceStudy, SummarizesHandMadeSteps) {
  const auto step = [](double ms, int iterations, bool converged) {
    return StudyStep{{{0.0, 1.0}}, ms, iterations, converged, 1e-4};
  };
  const StudySummary s = summarize_study(
      {step(4.0, 3, true), step(1.0, 8, false), step(2.0, 5, true), step(9.0, 4, true)});
  EXPECT_EQ(s.ms_median, 3.0);  // between 2 and 4
  EXPECT_EQ(s.ms_max, 9.0);
  EXPECT_EQ(s.iterations_median, 4.5);
  EXPECT_EQ(s.converged_fraction, 0.75);
  EXPECT_EQ(s.median_step, 2);  // the lower median time, 2 ms
  EXPECT_EQ(summarize_study({}).converged_fraction, 0.0);
}

TEST(ConvergenceStudy, RunsTheNamedSolversInTheirOrderFromTheSameState) {
  const BuiltCloth cloth = small_cloth();
  const auto study =
      run_convergence_study(cloth.model, cloth.state, options_with({"vbd", "implicit-pcg"}, 2));
  ASSERT_TRUE(study.has_value()) << study.error().message;
  ASSERT_EQ(study->solvers.size(), 2u);
  EXPECT_EQ(study->solvers[0].integrator, "vbd");
  EXPECT_EQ(study->solvers[1].integrator, "implicit-pcg");
  // Run alone, implicit-pcg takes the same iterations: it started from the same state.
  const auto alone =
      run_convergence_study(cloth.model, cloth.state, options_with({"implicit-pcg"}, 2));
  ASSERT_TRUE(alone.has_value());
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(alone->solvers[0].steps[k].iterations, study->solvers[1].steps[k].iterations);
    const auto& a = alone->solvers[0].steps[k].curve;
    const auto& b = study->solvers[1].steps[k].curve;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
      EXPECT_EQ(a[i].relative_gradient, b[i].relative_gradient);
  }
}

TEST(ConvergenceStudy, BadInputGetsOneClearError) {
  const std::string expected_names = [] {
    std::string names;
    for (const std::string& n : implicit_integrator_names())
      names += (names.empty() ? "" : ", ") + n;
    return names;
  }();
  EXPECT_EQ(error_of(options_with({"verlet"})),
            "unknown integrator 'verlet' (expected one of: " + expected_names + ")");
  EXPECT_EQ(error_of(options_with({"explicit"})),
            "integrator 'explicit' does not iterate to a tolerance, so it has no convergence "
            "curve (expected one of: " +
                expected_names + ")");
  EXPECT_EQ(error_of(options_with({"vbd", "implicit-pcg", "vbd"})),
            "integrator 'vbd' is named twice");
  EXPECT_EQ(error_of(options_with({}, 0)), "steps must be between 1 and 10000, got 0");
  ConvergenceStudyOptions options = options_with({});
  options.tolerance = 1.0;
  EXPECT_EQ(error_of(options), "tolerance must be between 0 and 1 (exclusive), got 1");
  options.tolerance = std::nan("");
  EXPECT_EQ(error_of(options), "tolerance must be between 0 and 1 (exclusive), got nan");
  options = options_with({});
  options.dt = 0.0;
  EXPECT_EQ(error_of(options), "time step (seconds) must be between 1e-06 and 10, got 0");

  const BuiltCloth cloth = small_cloth();
  ClothState state = cloth.state;
  state.positions.conservativeResize(state.positions.size() - 3);
  const auto wrong = run_convergence_study(cloth.model, state, options_with({}));
  ASSERT_FALSE(wrong.has_value());
  EXPECT_EQ(wrong.error().message, "the initial state has 24 particles but the cloth has 25");
  state = cloth.state;
  state.velocities[4] = std::nan("");
  const auto nan = run_convergence_study(cloth.model, state, options_with({}));
  ASSERT_FALSE(nan.has_value());
  EXPECT_EQ(nan.error().message, "the initial state has a non-finite position or velocity");
}

}  // namespace
}  // namespace animkit
