#pragma once
// `--integrator auto`: which implicit integrator is fastest on this scene, by measurement. No
// rule of thumb predicts it well (block-Jacobi PCG wins on soft cloth, multigrid and
// local/global on stiff cloth, the direct solver on small stiff cloth), so each candidate runs
// the scene's first steps from the same state and the fastest one that converged on every
// trial step wins.
#include <string_view>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/cloth_world.h"
#include "animkit/cloth/integrator_settings.h"
#include "animkit/core/result.h"

namespace animkit {

/// What one candidate did in the trial.
struct IntegratorTrial {
  std::string_view name;     ///< the registry's name
  int steps = 0;             ///< trial steps it ran (fewer when it could no longer win)
  double ms_per_step = 0.0;  ///< median wall time of those steps
  bool converged = false;    ///< every step it ran met the tolerance
  bool diverged = false;     ///< a step diverged (the candidate is out)
};

/// What choose_integrator() picked, and how every candidate fared.
struct IntegratorChoice {
  IntegratorSettings settings;          ///< the winner's defaults with the asked tolerance
  std::string_view name;                ///< the winner's registry name
  std::vector<IntegratorTrial> trials;  ///< every candidate, in registry order
};

/// Runs every implicit integrator of the registry (explicit Euler is not a candidate: it does
/// not minimize the incremental potential, and its stability depends on the substeps) for
/// `trial_steps` steps of `dt` from the scene's initial state at `tolerance`, and picks the
/// one with the lowest median time per step among those that converged on every step (if none
/// did, the one that converged on most, then fastest). A candidate stops early once its time so
/// far exceeds the best finished candidate's whole trial: it cannot win, and on stiff scenes the
/// slow ones would otherwise dominate the trial's cost. Errors: an invalid scene, dt or
/// tolerance, trial_steps < 1, or every candidate diverging.
Result<IntegratorChoice> choose_integrator(const ClothDesc& scene, double dt, double tolerance,
                                           int trial_steps = 3);

/// The same for a whole world: each candidate runs the world's first `trial_steps` steps of
/// its time step with its colliders, ground, contact, friction and air, and with contact or
/// air only the integrators that take energy terms (IntegratorEntry::takes_energy_terms)
/// compete. Errors: those of building the world, and as above.
Result<IntegratorChoice> choose_integrator(const ClothWorldDesc& world, double tolerance,
                                           int trial_steps = 3);

}  // namespace animkit
