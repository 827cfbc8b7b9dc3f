#pragma once
// metrics.json of `animkit cloth`: the run's settings, a summary and every step's report.
#include <optional>
#include <span>
#include <string>

#include "animkit/cloth/cloth_run.h"
#include "animkit/cloth/cloth_simulator.h"

namespace animkit {

struct ClothRunInfo {
  std::string integrator;  ///< e.g. "implicit-pcg"
  std::string scene;       ///< the --scene (built-in name or file), empty for the options' own
  int grid = 0;            ///< cells per side (0 if not a grid)
  int particles = 0, springs = 0;
  double dt = 0.0;  ///< seconds per frame
  int substeps = 1;
  double mass = 0.0, stiffness = 0.0, damping = 0.0, gravity = 0.0, tolerance = 0.0;
  /// Set when the run diverged: the error message (the steps are those before it).
  std::optional<std::string> divergence;
  /// The material preset of a physical sheet (empty: the lab's per-particle parameters, which
  /// mass, stiffness and damping then give; with a material those three are left out of the
  /// report), and the sheet's side.
  std::string material;
  double size = 0.0;
};

/// {"frames", "particles", "springs", "integrator", "diverged", "ms_per_step": {"median",
/// "mean"}, "newton_iterations": {"mean", "max"}, "final_energy", ..., "steps": [...]}.
std::string cloth_metrics_json(const ClothRunInfo& info, std::span<const StepReport> steps);

}  // namespace animkit
