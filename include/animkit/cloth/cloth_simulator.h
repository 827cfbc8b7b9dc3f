#pragma once
// A cloth being simulated: the model, its state, and the integrator that advances it. One
// entry point for the CLI, the viewer and the benchmarks; integrators are chosen by their
// settings (integrator_settings.h), listed once in integrator_registry.h.
#include <memory>
#include <optional>
#include <span>
#include <string_view>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/energy_term.h"
#include "animkit/cloth/integrator_settings.h"
#include "animkit/cloth/step_report.h"

namespace animkit {

/// How a ClothSimulator advances its cloth: the integrator and the substeps per step.
struct SimulationOptions {
  /// Which integrator, with its settings: the lab's implicit Euler (Newton + PCG) by default.
  IntegratorSettings integrator = NewtonSettings{};
  /// Substeps per step, >= 1; 0 picks the integrator's default (IntegratorEntry): 1000 for
  /// explicit Euler (the lab's), 1 for the implicit ones (stable at any step).
  int substeps = 0;

  /// An Error for substeps outside 0..kMaxSubsteps or invalid integrator settings, or none.
  std::optional<Error> validate() const;
  /// `substeps`, or the integrator's default when it is 0.
  int effective_substeps() const;
};

/// Positions or velocities beyond this size (scene units, per second) count as exploded.
constexpr double kExplodedMagnitude = 1e8;

/// A cloth being simulated: its model, its state and the integrator that advances it.
class ClothSimulator {
 public:
  /// Validates and builds everything once. Errors name the first problem.
  static Result<ClothSimulator> create(const ClothDesc& desc, const SimulationOptions& options);

  /// Takes over the moved-from simulator's cloth, which is left empty: fit only to be
  /// destroyed or assigned to.
  ClothSimulator(ClothSimulator&&) noexcept;
  /// Drops this simulator's cloth and takes over the moved-from one's, leaving that empty.
  ClothSimulator& operator=(ClothSimulator&&) noexcept;
  ~ClothSimulator();

  /// Advances by dt > 0 (seconds; the lab uses the frame's duration). If the state diverges
  /// (a non-finite or exploded position or velocity) the step is undone, the state stays as it
  /// was, and the error says which step and particle.
  Result<StepReport> step(double dt);

  /// Adds an energy term to every later step's potential (energy_term.h): contact, attachments,
  /// force fields. Newton's integrators take any term; VBD and local/global refuse with a
  /// message (see docs/stiff-cloth.md), as does explicit Euler.
  Result<void> add_energy_term(std::shared_ptr<EnergyTerm> term);

  /// Forces (3N, world units, particle-major like the state) added in every later step, held
  /// constant over each step like gravity: e.g. a mouse spring the caller re-evaluates per
  /// frame. Forces on pinned particles do nothing. Errors: wrong size, a non-finite value.
  Result<void> set_external_forces(const Eigen::VectorXd& forces);
  /// Removes the external forces.
  void clear_external_forces();

  /// Replaces the state (e.g. to restart from a saved one). Errors: wrong size, a non-finite
  /// value. Pinned particles get zero velocity.
  Result<void> set_state(const ClothState& state);

  /// The immutable model built from the description.
  const ClothModel& model() const;
  /// The current state. Its position and velocity buffers stay where they are for the
  /// simulator's whole life (steps, set_state and a diverged step's undo write into them), so
  /// a pointer or view into them (the Python module's numpy arrays) stays valid.
  const ClothState& state() const;
  /// The options it was created with.
  const SimulationOptions& options() const;
  /// Steps completed since creation (a diverged, undone step does not count).
  int steps_taken() const;

 private:
  struct Impl;
  explicit ClothSimulator(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit
