#pragma once
// Aggregate numbers of a cloth run (the summary the CLI writes and the README quotes).
#include <span>

#include "animkit/cloth/step_report.h"

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

}  // namespace animkit
