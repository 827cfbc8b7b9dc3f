#pragma once
// A cloth being simulated: the model, its state, and the integrator that advances it. One
// entry point for the CLI, the viewer and the benchmarks; integrators are chosen by an enum.
#include <memory>
#include <optional>
#include <span>
#include <string_view>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/implicit_euler.h"
#include "animkit/cloth/step_report.h"

namespace animkit {

enum class IntegratorKind {
  explicit_euler,   ///< "explicit": the lab's starting point, many substeps per frame
  implicit_direct,  ///< "implicit-direct": Newton, sparse LDL^T on the fixed pattern
  implicit_pcg,     ///< "implicit-pcg": Newton, block-Jacobi PCG (the fastest; the default)
};

std::string_view to_string(IntegratorKind kind);
std::optional<IntegratorKind> parse_integrator(std::string_view name);
std::span<const IntegratorKind> all_integrators();

struct SimulationOptions {
  IntegratorKind integrator = IntegratorKind::implicit_pcg;
  /// Substeps per step, >= 1; 0 picks the integrator's default: 1000 for explicit Euler (the
  /// lab's), 1 for implicit Euler (stable at any step).
  int substeps = 0;
  /// Newton settings for the implicit integrators (the linear solver follows `integrator`).
  ImplicitOptions implicit;

  std::optional<Error> validate() const;
  int effective_substeps() const;
};

/// Positions or velocities beyond this size (scene units, per second) count as exploded.
constexpr double kExplodedMagnitude = 1e8;

class ClothSimulator {
 public:
  /// Validates and builds everything once. Errors name the first problem.
  static Result<ClothSimulator> create(const ClothDesc& desc, const SimulationOptions& options);

  ClothSimulator(ClothSimulator&&) noexcept;
  ClothSimulator& operator=(ClothSimulator&&) noexcept;
  ~ClothSimulator();

  /// Advances by dt > 0 (seconds; the lab uses the frame's duration). If the state diverges
  /// (a non-finite or exploded position or velocity) the step is undone, the state stays as it
  /// was, and the error says which step and particle.
  Result<StepReport> step(double dt);

  /// Forces (3N, world units, particle-major like the state) added in every later step, held
  /// constant over each step like gravity: e.g. a mouse spring the caller re-evaluates per
  /// frame. Forces on pinned particles do nothing. Errors: wrong size, a non-finite value.
  Result<void> set_external_forces(const Eigen::VectorXd& forces);
  /// Removes the external forces.
  void clear_external_forces();

  /// Replaces the state (e.g. to restart from a saved one). Errors: wrong size, a non-finite
  /// value. Pinned particles get zero velocity.
  Result<void> set_state(const ClothState& state);

  const ClothModel& model() const;
  const ClothState& state() const;
  const SimulationOptions& options() const;
  int steps_taken() const;

 private:
  struct Impl;
  explicit ClothSimulator(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit
