#pragma once
// metrics.json of `animkit cloth`: the run's settings, a summary and every step's report.
#include <optional>
#include <span>
#include <string>

#include "animkit/cloth/cloth_run.h"
#include "animkit/cloth/cloth_simulator.h"

namespace animkit {

/// The settings of a cloth run that metrics.json reports beside its steps.
struct ClothRunInfo {
  std::string integrator;  ///< e.g. "implicit-pcg"
  std::string scene;       ///< the --scene (built-in name or file), empty for the options' own
  int grid = 0;            ///< cells per side (0 if not a grid)
  /// Particles of the cloth model.
  int particles = 0, springs = 0;  ///< springs of the cloth model
  double dt = 0.0;  ///< seconds per frame
  int substeps = 1;  ///< substeps per frame in effect (>= 1)
  /// Mass per particle of the lab's parameters (unused with a material).
  double mass = 0.0, stiffness = 0.0, damping = 0.0, gravity = 0.0, tolerance = 0.0;
  /// Set when the run diverged: the error message (the steps are those before it).
  std::optional<std::string> divergence;
  /// The material preset of a physical sheet (empty: the lab's per-particle parameters, which
  /// mass, stiffness and damping then give; with a material those three are left out of the
  /// report).
  std::string material;
  double size = 0.0;  ///< a grid sheet's side length (scene units; m with a material), else 0
  /// \var stiffness
  /// Stiffness k of every spring, force per unit length (lab's parameters; unused with a
  /// material).
  /// \var damping
  /// Spring dashpot coefficient (lab's parameters; unused with a material).
  /// \var gravity
  /// Gravity along -y, scene units/s^2.
  /// \var tolerance
  /// The integrator's convergence tolerance; 0 for one that does not iterate (explicit Euler).
};

/// {"frames", "particles", "springs", "integrator", "diverged", "ms_per_step": {"median",
/// "mean"}, "newton_iterations": {"mean", "max"}, "final_energy", ..., "steps": [...]}.
std::string cloth_metrics_json(const ClothRunInfo& info, std::span<const StepReport> steps);

}  // namespace animkit
