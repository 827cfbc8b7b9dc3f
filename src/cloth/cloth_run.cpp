#include "animkit/cloth/cloth_run.h"

#include <algorithm>
#include <vector>

namespace animkit {

ClothRunSummary summarize(std::span<const StepReport> steps) {
  ClothRunSummary s;
  s.frames = static_cast<int>(steps.size());
  if (steps.empty()) return s;
  std::vector<double> ms;
  int converged = 0;
  for (const StepReport& r : steps) {
    ms.push_back(r.ms);
    s.ms_per_step_mean += r.ms;
    s.newton_iterations_mean += r.newton_iterations;
    s.newton_iterations_max = std::max(s.newton_iterations_max, r.newton_iterations);
    s.linear_iterations_mean += r.linear_iterations;
    s.line_search_steps_mean += r.line_search_steps;
    converged += r.converged ? 1 : 0;
  }
  const double n = static_cast<double>(steps.size());
  s.ms_per_step_mean /= n;
  s.newton_iterations_mean /= n;
  s.linear_iterations_mean /= n;
  s.line_search_steps_mean /= n;
  s.converged_fraction = converged / n;
  s.final_energy = steps.back().energy;
  std::sort(ms.begin(), ms.end());
  const std::size_t mid = ms.size() / 2;
  s.ms_per_step_median = ms.size() % 2 == 1 ? ms[mid] : 0.5 * (ms[mid - 1] + ms[mid]);
  return s;
}

Result<ClothRun> run_cloth(ClothSimulator& sim, int frames, double dt,
                           const ClothFrameCallback& on_frame) {
  ClothRun run;
  run.steps.reserve(static_cast<std::size_t>(std::max(frames, 0)));
  for (int frame = 1; frame <= frames; ++frame) {
    auto report = sim.step(dt);
    if (!report) {
      run.divergence = report.error().message;
      break;
    }
    run.steps.push_back(std::move(*report));
    if (on_frame) {
      if (auto ok = on_frame(frame, sim, run.steps.back()); !ok) return fail(ok.error().message);
    }
  }
  return run;
}

}  // namespace animkit
