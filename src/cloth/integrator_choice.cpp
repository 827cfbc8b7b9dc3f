#include "animkit/cloth/integrator_choice.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <tuple>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/parameter_ranges.h"

namespace animkit {

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The trial: `simulate(entry, options)` makes a candidate's simulator, or none when the entry
// does not compete on this scene.
using SimulatorMaker =
    std::function<Result<std::optional<ClothSimulator>>(const IntegratorEntry&, SimulationOptions)>;

Result<IntegratorChoice> run_trial(const SimulatorMaker& simulate, double dt, double tolerance,
                                   int trial_steps) {
  if (trial_steps < 1)
    return fail("trial steps must be at least 1, got " + std::to_string(trial_steps));
  if (!kTimeStepRange.contains(dt)) return fail(kTimeStepRange.refusal("time step", dt));
  IntegratorChoice choice;
  double best_total = std::numeric_limits<double>::infinity();  // of a converged candidate
  std::tuple<int, double> best_rank{1, 0.0};  // (not converged, ms per step): lower wins
  const IntegratorEntry* best = nullptr;
  for (const IntegratorEntry& entry : cloth_integrators()) {
    if (!tolerance_of(entry.defaults)) continue;  // explicit Euler
    SimulationOptions options{entry.defaults, 0};
    set_tolerance(options.integrator, tolerance);
    auto sim = simulate(entry, options);
    if (!sim) return fail(sim.error().message);  // the scene or the tolerance is invalid
    if (!*sim) continue;

    IntegratorTrial trial{.name = entry.name, .converged = true};
    std::vector<double> ms;
    double total = 0.0;
    for (int step = 0; step < trial_steps && total <= best_total; ++step) {
      auto report = (*sim)->step(dt);
      if (!report) {  // diverged: the candidate is out
        trial.diverged = true;
        break;
      }
      ms.push_back(report->ms);
      total += report->ms;
      trial.converged = trial.converged && report->converged;
    }
    trial.steps = static_cast<int>(ms.size());
    if (!ms.empty()) trial.ms_per_step = median(ms);
    choice.trials.push_back(trial);
    // Only a full trial competes; a candidate stopped early was already slower than the best.
    if (trial.diverged || trial.steps < trial_steps) continue;
    const std::tuple<int, double> rank{trial.converged ? 0 : 1, trial.ms_per_step};
    if (!best || rank < best_rank) {
      best = &entry;
      best_rank = rank;
    }
    if (trial.converged) best_total = std::min(best_total, total);
  }
  if (!best) return fail("every integrator diverged on this scene's first steps");
  choice.settings = best->defaults;
  set_tolerance(choice.settings, tolerance);
  choice.name = best->name;
  return choice;
}

}  // namespace

Result<IntegratorChoice> choose_integrator(const ClothDesc& scene, double dt, double tolerance,
                                           int trial_steps) {
  const SimulatorMaker simulate =
      [&scene](const IntegratorEntry&,
               SimulationOptions options) -> Result<std::optional<ClothSimulator>> {
    auto sim = ClothSimulator::create(scene, options);
    if (!sim) return fail(sim.error().message);
    return std::optional<ClothSimulator>(std::move(*sim));
  };
  return run_trial(simulate, dt, tolerance, trial_steps);
}

Result<IntegratorChoice> choose_integrator(const ClothWorldDesc& world, double tolerance,
                                           int trial_steps) {
  if (auto error = world.validate()) return fail(error->message);
  auto cloth = build_world_cloth(world);
  if (!cloth) return fail(cloth.error().message);
  const bool has_terms = world.has_contact() || world.air.has_value();
  const SimulatorMaker simulate =
      [&](const IntegratorEntry& entry,
          SimulationOptions options) -> Result<std::optional<ClothSimulator>> {
    if (has_terms && !entry.takes_energy_terms) return std::optional<ClothSimulator>();
    ClothWorldDesc desc = world;
    desc.simulation.integrator = options.integrator;  // the world's substeps kept
    auto built = build_cloth_world(desc, *cloth);
    if (!built) return fail(built.error().message);
    return std::optional<ClothSimulator>(std::move(built->simulator));
  };
  return run_trial(simulate, world.time_step, tolerance, trial_steps);
}

}  // namespace animkit
