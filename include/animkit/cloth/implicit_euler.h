#pragma once
// Implicit Euler for the mass-spring cloth, exactly as docs/implicit-step.md poses it: minimize
// g(x) (see incremental_potential.h) by Newton's method from x = y with a backtracking
// (Armijo) line search, then v = (x - x_n) / h. A step is a recipe of named stages:
// predict y -> Newton iterations (gradient, Hessian, linear solve, line search) -> velocities.
#include <memory>
#include <optional>

#include "animkit/cloth/block_hessian.h"
#include "animkit/cloth/block_jacobi_pcg.h"
#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/integrator.h"
#include "animkit/cloth/integrator_settings.h"
#include "animkit/cloth/multigrid_pcg.h"
#include "animkit/cloth/step_report.h"
#include "animkit/core/result.h"

namespace animkit {

struct GradientStop;  // implicit_substep.h

/// Advances a cloth by implicit Euler steps. Holds the workspace (vectors, block Hessian,
/// preconditioner; for the direct solver the pattern and symbolic factorization) sized once for
/// its model: the PCG path allocates nothing in the Newton loop. The direct path hands Eigen's
/// LDL^T a matrix already in fill-reducing order, so no reordered copy is made per
/// factorization; Eigen still allocates O(N) scratch in each numeric factorization.
class ImplicitEuler final : public ClothIntegrator {
 public:
  /// Integrates `model` (shared: kept alive by this integrator) with the valid Newton settings
  /// `options`; builds the chosen linear solver's structures once.
  ImplicitEuler(std::shared_ptr<const ClothModel> model, const NewtonSettings& options);
  ~ImplicitEuler() override;

  /// One step of h > 0 from `state` into `state`; adds its numbers to `report`.
  /// `external_forces`: see IncrementalPotential::prepare().
  void step(ClothState& state, double h, StepReport& report,
            const Eigen::VectorXd* external_forces = nullptr) override;
  /// Newton takes any term: its gradient and Hessian join g's (see energy_term.h).
  bool add_energy_term(std::shared_ptr<EnergyTerm> term) override;

 private:
  struct DirectSolver;
  // The stages of a substep, in order (see step()).
  double start_substep(const ClothState& state, double h, const Eigen::VectorXd* external_forces,
                       StepReport& report);
  double lowest_start(const Eigen::VectorXd& start, double bound) const;
  bool next_lagging_pass(const GradientStop& stop, double& gradient_norm, StepReport& report);
  double newton_direction(double gradient_norm, double relative_gradient, IterationRecord& record,
                          StepReport& report);
  bool solve_newton_system(double relative_gradient, IterationRecord& record);
  std::optional<double> verified_speed(double h, IterationRecord& record, StepReport& report);
  double step_bound(StepReport& report);
  std::optional<double> line_search(double slope, double bound, IterationRecord& record,
                                    StepReport& report);
  void extend_projected_step(double& decrease, double& alpha);
  double accept_step(StepReport& report);
  double arrive_at_iterate(StepReport& report);

  // Shared and immutable: the reference below stays valid however this integrator moves.
  std::shared_ptr<const ClothModel> model_owner_;
  const ClothModel& model_;
  NewtonSettings options_;
  IncrementalPotential potential_;
  BlockHessian hessian_;
  BlockJacobiPcg pcg_;
  std::unique_ptr<MultigridPcg> multigrid_;  // only with LinearSolverKind::multigrid
  std::unique_ptr<DirectSolver> direct_;     // only with LinearSolverKind::direct
  Eigen::VectorXd x_, gradient_, dx_, trial_, rhs_;
};

}  // namespace animkit
