#pragma once
// What one cloth step did: the numbers the CLI writes, the viewer plots and tests check.
#include <vector>

namespace animkit {

/// One iteration of an implicit integrator (recorded when its settings ask for it): Newton
/// iterations, local/global iterations, VBD sweeps. The fields after `ms` are Newton's.
struct IterationRecord {
  double gradient_norm = 0.0;  ///< |grad g| at the iteration's end (the accepted x_{k+1})
  /// Wall time from the substep's start to the end of this iteration (ms), the x-axis of the
  /// convergence study.
  double ms = 0.0;
  double objective = 0.0;        ///< g(x_k), evaluated on its own
  double objective_after = 0.0;  ///< g(x_k + alpha dx), evaluated on its own (for checking)
  double decrease = 0.0;         ///< g(x_k + alpha dx) - g(x_k) as the line search computed it
  double slope = 0.0;            ///< grad g(x_k) . dx (negative for a descent direction)
  double alpha = 0.0;            ///< accepted step length
  int line_search_steps = 0;     ///< backtracking reductions before acceptance
  int linear_iterations = 0;     ///< PCG iterations of this iteration's solve(s) (0: direct)
  bool projected = false;        ///< solved with the projected Hessian (see HessianProjection)
};

/// What one ClothSimulator::step() did: its substeps, the solver's iterations and stopping
/// test, the energy after it, and where its time went.
struct StepReport {
  int substeps = 1;       ///< substeps the step is split into (SimulationOptions), >= 1
  int substeps_done = 0;  ///< substeps completed so far (while the step runs)
  /// Iterations of the implicit solver (Newton iterations, local/global iterations, VBD
  /// sweeps), summed over substeps (0 for explicit Euler).
  int newton_iterations = 0;
  int line_search_steps = 0;         ///< backtracking reductions, summed
  int linear_iterations = 0;         ///< PCG iterations, summed (0 for a direct solve)
  int projected_iterations = 0;      ///< Newton iterations that needed the projected Hessian
  double gradient_norm_start = 0.0;  ///< |grad g| at x = y (first substep)
  double gradient_norm_end = 0.0;    ///< |grad g| at the accepted x (last substep)
  /// The |grad g| Newton stopped at: tolerance x the start, or the rounding floor when higher.
  double gradient_tolerance = 0.0;
  /// |dx|_inf / h of the last Newton direction computed (m/s; 0 before the first), the
  /// quantity NewtonSettings::velocity_tolerance bounds.
  double newton_speed_end = 0.0;
  /// The newton_speed_end a substep may end at (velocity_tolerance x the bounding box's
  /// diagonal, m/s; 0 when that stop is off): a converged step met this or gradient_tolerance.
  double speed_tolerance = 0.0;
  bool converged = true;  ///< every substep reached its stopping test
  double energy = 0.0;    ///< total mechanical energy after the step (cloth_energy().total)
  double ms = 0.0;        ///< wall time of the whole step
  /// Lagged minimizations (friction's lagging passes, friction.h), summed over substeps: one
  /// per substep of a Newton integrator, plus one per re-lag that moved the minimum (0 for
  /// the integrators that take no energy terms).
  int friction_iterations = 0;
  /// Time per stage (ms, summed over substeps): gradient and objective evaluations, Hessian
  /// assembly, linear solves, line search; with energy terms also their per-iterate updates
  /// (e.g. finding contact pairs) and step bounds (e.g. continuous collision detection).
  /// This one: gradient and objective evaluations.
  double ms_gradient = 0.0, ms_hessian = 0.0, ms_linear_solve = 0.0, ms_line_search = 0.0;
  /// Time in energy terms' per-iterate updates, e.g. finding contact pairs (ms, summed over
  /// substeps).
  double ms_term_updates = 0.0, ms_step_bound = 0.0;  ///< time in the terms' step bounds (ms)
  /// The smallest fraction of a Newton step (or of the move from x_n to y) the energy terms
  /// admitted (EnergyTerm::max_step), 1 when none bounded a step.
  double step_bound_min = 1.0;
  /// Whether a contact term (contact.h) filled contact_pairs and min_contact_distance in, at
  /// the step's end.
  bool has_contact = false;
  int contact_pairs = 0;  ///< pairs closer than the contact distance (thickness)
  /// The smallest distance among those pairs (m; the contact distance when none is that close).
  double min_contact_distance = 0.0;
  std::vector<IterationRecord> iterations;  ///< empty unless recording was asked for
  /// \var ms_hessian
  /// Time in Hessian assembly (ms, summed over substeps).
  /// \var ms_linear_solve
  /// Time in linear solves (ms, summed over substeps).
  /// \var ms_line_search
  /// Time in line searches (ms, summed over substeps).
};

}  // namespace animkit
