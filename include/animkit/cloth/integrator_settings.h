#pragma once
// Every cloth integrator's own settings, and the variant that says which integrator a simulation
// uses. The implicit ones all minimize the same incremental potential g (incremental_potential.h)
// and stop on the same test, |grad g| <= tolerance |grad g at the prediction y| (or the rounding
// floor, whichever is higher), so their results and costs can be compared one to one.
#include <array>
#include <optional>
#include <string_view>
#include <variant>

#include "animkit/core/enum_names.h"
#include "animkit/core/result.h"

namespace animkit {

/// Explicit (symplectic) Euler: the lab's starting point. Needs many substeps to stay stable.
/// Its only setting is how many substeps a step takes (SimulationOptions::substeps; the registry
/// gives the lab's 1000 as its default).
struct ExplicitEulerSettings {
  /// Always none: there is nothing to check.
  std::optional<Error> validate() const { return std::nullopt; }
};

/// How each Newton iteration solves Hessian * dx = -gradient. All reach the same x.
enum class LinearSolverKind {
  /// Sparse LDL^T (Eigen SimplicialLDLT) on the fixed pattern, stored as its upper triangle
  /// in AMD order: ordering and symbolic analysis are done once per model, each iteration only
  /// factorizes numerically.
  direct,
  /// Conjugate gradients with a block-Jacobi preconditioner, solved inexactly: to a relative
  /// residual that tightens as Newton converges (Eisenstat-Walker forcing), so early
  /// iterations cost a few matrix-vector products and Newton keeps its fast local convergence.
  pcg,
  /// Conjugate gradients with a smoothed aggregation multigrid V-cycle as preconditioner
  /// (Tamstorf, Jones & McCormick 2015, multigrid_pcg.h), with the same forcing as pcg. Its
  /// iteration count barely grows with stiffness and resolution, where block Jacobi's does.
  multigrid,
};

/// When Newton uses the projected (clamped, PSD) spring Hessian instead of the exact one.
/// Either way every Newton direction is a descent direction.
enum class HessianProjection {
  /// The exact Hessian, which converges quadratically, as long as the whole system matrix
  /// M/h^2 + H stays positive definite (the inertia term usually outweighs compressed
  /// springs); an iteration whose solve meets negative curvature (a non-positive LDL^T pivot,
  /// or p.Ap <= 0 in CG) is redone with the projected Hessian.
  when_indefinite,
  /// The projected Hessian every iteration: SPD by construction, but only linearly
  /// convergent where springs are compressed.
  always,
  /// `always` while energy terms join the step (contact, friction, wind: any EnergyTerm),
  /// `when_indefinite` otherwise: the fast settings' choice (use_fast_settings). Cloth
  /// folding onto colliders meets negative curvature in most iterations, and the exact
  /// attempt when_indefinite makes first is thrown away there; a free sheet's exact
  /// iterations mostly succeed and converge quadratically (docs/contact.md, "The projected
  /// Hessian at once with contact").
  with_terms,
};

/// Each HessianProjection's name (scene files; enum_names.h), in the enum's order.
inline constexpr std::array<std::string_view, 3> kHessianProjectionNames = {
    "when_indefinite", "always", "with_terms"};

/// Implicit Euler by Newton's method with a backtracking line search (docs/implicit-step.md).
struct NewtonSettings {
  LinearSolverKind linear_solver = LinearSolverKind::pcg;  ///< how each Newton system is solved
  /// Stops when |grad g| <= tolerance * |grad g at x = y|. (0, 1).
  double tolerance = 1e-6;
  int max_iterations = 50;         ///< Newton iterations per substep, >= 1
  double beta = 0.5;               ///< line-search step shrink factor, in (0, 1)
  double gamma = 1e-4;             ///< Armijo sufficient-decrease constant, in (0, 1)
  int max_line_search_steps = 50;  ///< backtracking reductions before giving up, >= 1
  /// When the projected spring Hessian replaces the exact one.
  HessianProjection projection = HessianProjection::when_indefinite;
  bool record_iterations = false;  ///< fill StepReport::iterations
  /// IPC's stopping test on the Newton direction dx (Li et al. 2020; ipc-sim/IPC,
  /// Optimizer.cpp, "distToOpt_PN < tol * bboxDiagSize * dt"): a substep also ends when
  /// |dx|_inf / h <= velocity_tolerance * L, i.e. when no particle's next correction moves it
  /// faster than this fraction of the cloth's size L per second (L the diagonal of the cloth's
  /// bounding box at the substep's start). Unlike the relative gradient it means the same on
  /// any mesh and does not wander where buckling cloth has several minima. 0: off; else
  /// [0, 1). IPC's scripts mostly use 1e-3.
  double velocity_tolerance = 0.0;
  /// The relative residual CG solves each Newton system to (inexact Newton, Eisenstat and
  /// Walker 1996), in [0, 1). 0 (default): adaptive, 1% of the relative gradient, which saves
  /// Newton iterations when the goal is a tight gradient. A fixed forcing term such as 0.1
  /// suits a stop on the step's size (velocity_tolerance): CG's last digits only refine a
  /// correction that the next iteration redoes.
  double linear_forcing = 0.0;

  /// An Error naming the first setting out of its range above, or none.
  std::optional<Error> validate() const;
};

/// Vertex Block Descent (Chen, Macklin et al. 2024): coloured Gauss-Seidel sweeps of per-vertex
/// 3x3 Newton steps on g, each guarded so that g never increases (vertex_block_descent.h).
struct VbdSettings {
  /// Stops when |grad g| <= tolerance * |grad g at x = y|, like Newton. (0, 1).
  double tolerance = 1e-6;
  int max_iterations = 1000;       ///< sweeps (over all colours) per substep, >= 1
  bool record_iterations = false;  ///< fill StepReport::iterations
  /// Sweeps between stopping tests (each costs a full gradient), >= 1. The test also runs
  /// after the last sweep, and after every sweep when recording.
  int check_interval = 1;
  /// Chebyshev acceleration's spectral radius estimate rho (Wang 2015, as VBD section 3.8
  /// applies it), in [0, 1); 0 turns it off. An accelerated iterate that does not decrease g
  /// is dropped and the acceleration restarts, so g still decreases every sweep. Near 1 suits
  /// stiff cloth (slow Gauss-Seidel convergence); on soft cloth VBD stops before it matters.
  double chebyshev_rho = 0.999;
  /// Local Armijo constant of each vertex's backtracking, in (0, 1).
  double gamma = 1e-4;
  int max_backtracks = 10;  ///< halvings of a vertex's step before it stays put, >= 0

  /// An Error naming the first setting out of its range above, or none.
  std::optional<Error> validate() const;
};

/// Implicit Euler by the local/global method (Liu et al. 2013, "Fast simulation of mass-spring
/// systems"): each iteration is x <- x - P^-1 grad g(x) with a constant matrix P that
/// majorizes the Hessian of g, factorized once per time step size (local_global.h). Optionally
/// accelerated by Chebyshev semi-iteration (Wang 2015, "A Chebyshev semi-iterative approach
/// for accelerating projective and position-based dynamics").
struct LocalGlobalSettings {
  /// Stops when |grad g| <= tolerance * |grad g at x = y| (the same test as Newton). (0, 1).
  double tolerance = 1e-6;
  int max_iterations = 500;  ///< local/global iterations per substep, >= 1
  /// Chebyshev acceleration. Off: the plain method, which decreases g at every iteration.
  bool chebyshev = true;
  /// Wang's estimate rho of the plain iteration's spectral radius, in (0, 1). Pick it from a
  /// run of the plain method: the ratio |grad g_{k+1}| / |grad g_k| it settles to. Too low
  /// accelerates little; too high (past the true radius) oscillates and, with `monotone`,
  /// restarts often. Loose tolerances end before the asymptotic rate matters and do best a
  /// little below it (the default suits 1e-2 on stiff cloth); tight ones want it close to 1.
  double spectral_radius = 0.99;
  int chebyshev_delay = 10;  ///< plain iterations before the acceleration starts, >= 0
  /// With Chebyshev: reject an accelerated iterate that does not decrease g (or does not
  /// descend), take the plain step instead and restart the Chebyshev sequence, so g still
  /// decreases at every iteration. Costs one evaluation of g's difference per iteration.
  bool monotone = true;
  bool record_iterations = false;  ///< fill StepReport::iterations

  /// An Error naming the first setting out of its range above (tolerance, max_iterations,
  /// spectral_radius, chebyshev_delay), or none.
  std::optional<Error> validate() const;
};

/// Which integrator a simulation uses, with its settings. Adding an integrator adds one
/// alternative here and one entry in the registry (integrator_registry.h).
using IntegratorSettings =
    std::variant<ExplicitEulerSettings, NewtonSettings, VbdSettings, LocalGlobalSettings>;

/// The first invalid setting, or nothing.
std::optional<Error> validate(const IntegratorSettings& settings);

/// The stopping tolerance of an implicit integrator (nothing for explicit Euler), and setting it
/// (ignored by explicit Euler, which has no iterations to stop).
std::optional<double> tolerance_of(const IntegratorSettings& settings);
void set_tolerance(IntegratorSettings& settings, double tolerance);
/// Asks an implicit integrator to record every iteration into StepReport::iterations.
void set_record_iterations(IntegratorSettings& settings, bool record);

}  // namespace animkit
