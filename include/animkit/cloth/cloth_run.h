#pragma once
// A cloth run: the per-frame loop every shell shares (step, record, stop on divergence, hand
// each frame to the caller), and the aggregate numbers of a run (the summary the CLI writes
// and the README quotes).
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/step_report.h"
#include "animkit/core/result.h"

namespace animkit {

struct ClothRunSummary {
  int frames = 0;  ///< steps taken
  double ms_per_step_median = 0.0;
  double ms_per_step_mean = 0.0;
  double newton_iterations_mean = 0.0;  ///< per step
  int newton_iterations_max = 0;
  double linear_iterations_mean = 0.0;  ///< PCG iterations per step
  double line_search_steps_mean = 0.0;
  double converged_fraction = 0.0;  ///< steps that reached their gradient tolerance
  double final_energy = 0.0;        ///< total energy after the last step
};

ClothRunSummary summarize(std::span<const StepReport> steps);

/// What a run did: one report per step taken and, when a step diverged, its message (the
/// simulator kept the state before that step; the run stopped there).
struct ClothRun {
  std::vector<StepReport> steps;
  std::optional<std::string> divergence;
};

/// Called after every step with the frame number (1-based), the simulator in its new state and
/// the step's report (to write a cache frame, draw a picture, update a progress line). An
/// error stops the run.
using ClothFrameCallback =
    std::function<Result<void>(int frame, const ClothSimulator& sim, const StepReport& step)>;

/// Advances `sim` by `frames` steps of dt seconds. A diverged step ends the run (its message in
/// ClothRun::divergence, not an error); a failing callback ends it with the callback's error.
Result<ClothRun> run_cloth(ClothSimulator& sim, int frames, double dt,
                           const ClothFrameCallback& on_frame = {});

}  // namespace animkit
