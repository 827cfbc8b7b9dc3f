#pragma once
// Implicit Euler for the mass-spring cloth, exactly as SPEC.md section 4 poses it: minimize
// g(x) (see incremental_potential.h) by Newton's method from x = y with a backtracking
// (Armijo) line search, then v = (x - x_n) / h. A step is a recipe of named stages:
// predict y -> Newton iterations (gradient, Hessian, linear solve, line search) -> velocities.
#include <memory>
#include <optional>

#include "animkit/cloth/block_hessian.h"
#include "animkit/cloth/block_jacobi_pcg.h"
#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/step_report.h"
#include "animkit/core/result.h"

namespace animkit {

/// How each Newton iteration solves Hessian * dx = -gradient. Both reach the same x.
enum class LinearSolverKind {
  /// Sparse LDL^T (Eigen SimplicialLDLT) on the fixed pattern, stored as its upper triangle
  /// in AMD order: ordering and symbolic analysis are done once per model, each iteration only
  /// factorizes numerically.
  direct,
  /// Conjugate gradients with a block-Jacobi preconditioner, solved inexactly: to a relative
  /// residual that tightens as Newton converges (Eisenstat-Walker forcing), so early
  /// iterations cost a few matrix-vector products and Newton keeps its fast local convergence.
  pcg,
};

/// When Newton uses the projected (clamped, PSD) spring Hessian instead of the exact one.
/// Either way every Newton direction is a descent direction.
enum class HessianProjection {
  /// The exact Hessian, which converges quadratically, as long as the whole system matrix
  /// M/h^2 + H stays positive definite (the inertia term usually outweighs compressed
  /// springs); an iteration whose solve meets negative curvature (a non-positive LDL^T pivot,
  /// or p.Ap <= 0 in CG) is redone with the projected Hessian. Measured on a stiff, buckling
  /// cloth: 5-6 Newton iterations per step where always projecting takes 16-19.
  when_indefinite,
  /// The projected Hessian every iteration: SPD by construction, but only linearly
  /// convergent where springs are compressed.
  always,
};

struct ImplicitOptions {
  LinearSolverKind linear_solver = LinearSolverKind::pcg;
  /// Newton stops when |grad g| <= tolerance * |grad g at x = y|. (0, 1).
  double tolerance = 1e-6;
  int max_newton_iterations = 50;  ///< >= 1
  double beta = 0.5;               ///< line-search step shrink factor, in (0, 1)
  double gamma = 1e-4;             ///< Armijo sufficient-decrease constant, in (0, 1)
  int max_line_search_steps = 50;  ///< backtracking reductions before giving up, >= 1
  HessianProjection projection = HessianProjection::when_indefinite;
  bool record_iterations = false;  ///< fill StepReport::iterations

  std::optional<Error> validate() const;
};

/// Advances a cloth by implicit Euler steps. Holds the workspace (vectors, block Hessian,
/// preconditioner; for the direct solver the pattern and symbolic factorization) sized once for
/// its model: the PCG path allocates nothing in the Newton loop. The direct path hands Eigen's
/// LDL^T a matrix already in fill-reducing order, so no reordered copy is made per
/// factorization; Eigen still allocates O(N) scratch in each numeric factorization.
class ImplicitEuler {
 public:
  ImplicitEuler(const ClothModel& model, const ImplicitOptions& options);
  ~ImplicitEuler();

  /// One step of h > 0 from `state` into `state`; adds its numbers to `report`.
  /// `external_forces`: see IncrementalPotential::prepare().
  void step(ClothState& state, double h, StepReport& report,
            const Eigen::VectorXd* external_forces = nullptr);

 private:
  struct DirectSolver;
  bool solve_newton_system(double relative_gradient, NewtonIterationRecord& record);

  const ClothModel& model_;
  ImplicitOptions options_;
  IncrementalPotential potential_;
  BlockHessian hessian_;
  BlockJacobiPcg pcg_;
  std::unique_ptr<DirectSolver> direct_;
  double spring_force_scale_ = 0.0;  // |(k L) over springs|, for the rounding floor
  Eigen::VectorXd x_, gradient_, dx_, trial_, rhs_;
};

}  // namespace animkit
