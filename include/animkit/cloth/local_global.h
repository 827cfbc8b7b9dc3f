#pragma once
// Implicit Euler by the local/global method of Liu et al. 2013 ("Fast simulation of
// mass-spring systems"), with Chebyshev acceleration (Wang 2015, "A Chebyshev semi-iterative
// approach for accelerating projective and position-based dynamics").
//
// A spring's energy is 1/2 k (|x_a - x_b| - L)^2 = min over |d| = L of 1/2 k |x_a - x_b - d|^2,
// so minimizing g alternates a local step (each d_s = L u_s) and a global step, one solve with
// the constant matrix P of local_global_system.h. The two steps together are exactly
//   x <- x - P^-1 grad g(x)
// (Liu et al., section 3.3), the form used here: the gradient is IncrementalPotential's, the
// one the stopping test needs anyway, and the dashpots, bends, inertia, external forces and
// pins all enter through it. P majorizes g's Hessian everywhere, so
//   g(x - P^-1 grad) <= g(x) - 1/2 grad^T P^-1 grad:
// the plain method decreases g at every iteration. It stops on Newton's test
// (|grad g| <= max(tolerance |grad g(y)|, IncrementalPotential::gradient_floor())).
#include <Eigen/Core>
#include <memory>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/integrator.h"
#include "animkit/cloth/integrator_settings.h"
#include "animkit/cloth/local_global_system.h"
#include "animkit/cloth/step_report.h"

namespace animkit {

/// Advances a cloth by implicit Euler steps solved by local/global iterations. Orders and
/// analyses P once per model, factorizes it once per substep size (again only when h
/// changes), and allocates nothing per iteration (unless recording iterations).
class LocalGlobal final : public ClothIntegrator {
 public:
  /// Integrates `model` (shared: kept alive by this integrator) with the valid `settings`;
  /// orders and analyses P once.
  LocalGlobal(std::shared_ptr<const ClothModel> model, const LocalGlobalSettings& settings);

  /// One substep of h > 0 from `state` into `state`; adds its numbers to `report` (the
  /// factorization's time, when h changed, goes to ms_hessian).
  void step(ClothState& state, double h, StepReport& report,
            const Eigen::VectorXd* external_forces = nullptr) override;

  /// The factored matrix (for tests and benchmarks: its size, when it was refactored).
  const LocalGlobalSystem& system() const { return system_; }

 private:
  // Shared and immutable: the reference below stays valid however this integrator moves.
  std::shared_ptr<const ClothModel> model_owner_;
  const ClothModel& model_;
  LocalGlobalSettings settings_;
  IncrementalPotential potential_;
  LocalGlobalSystem system_;
  // x_k, x_{k-1} (Chebyshev), grad g(x_k), the plain direction -P^-1 grad and the step taken.
  Eigen::VectorXd x_, previous_, gradient_, direction_, step_;
};

}  // namespace animkit
