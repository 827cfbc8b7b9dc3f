#include "animkit/cloth/implicit_euler.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/cloth/hessian_pattern.h"
#include "animkit/cloth/implicit_substep.h"
#include "animkit/core/validation.h"

namespace animkit {

namespace {
// The relative residual a direction that passes the velocity test is solved to again before
// the substep ends on it (when linear_forcing is looser). CG stopped at 10% has resolved the
// stiff components and left the soft ones (hanging, folding) short, so such a direction can
// understate the distance to the minimum. Measured on drape-sphere 41 x 41 (60 frames): without
// this check 6 of the 25 resting steps ended more than 0.1 mm (up to 2.5 mm) from the
// reference's step from the same state and an impact step 45 mm; with it none, and 15 mm.
constexpr double kVerifyingForcing = 0.01;

// Longest extension of a projected Newton step: 2^10 times its length.
constexpr int kMaxStepDoublings = 10;

// CG's iteration cap for one Newton system.
int cg_iteration_cap(const ClothModel& model) {
  return 3 * model.particle_count();
}
}  // namespace

std::optional<Error> NewtonSettings::validate() const {
  if (!std::isfinite(tolerance) || tolerance <= 0.0 || tolerance >= 1.0) {
    return Error{"tolerance must be in (0, 1), got " + format_number(tolerance)};
  }
  if (max_iterations < 1) {
    return Error{"max Newton iterations must be at least 1, got " + std::to_string(max_iterations)};
  }
  if (!std::isfinite(beta) || beta <= 0.0 || beta >= 1.0) {
    return Error{"line-search beta must be in (0, 1), got " + format_number(beta)};
  }
  if (!std::isfinite(gamma) || gamma <= 0.0 || gamma >= 1.0) {
    return Error{"line-search gamma must be in (0, 1), got " + format_number(gamma)};
  }
  if (!std::isfinite(velocity_tolerance) || velocity_tolerance < 0.0 ||
      velocity_tolerance >= 1.0) {
    return Error{"velocity tolerance must be in [0, 1), got " + format_number(velocity_tolerance)};
  }
  if (!std::isfinite(linear_forcing) || linear_forcing < 0.0 || linear_forcing >= 1.0) {
    return Error{"linear forcing must be in [0, 1), got " + format_number(linear_forcing)};
  }
  if (max_line_search_steps < 1) {
    return Error{"max line-search steps must be at least 1, got " +
                 std::to_string(max_line_search_steps)};
  }
  return std::nullopt;
}

struct ImplicitEuler::DirectSolver {
  // The upper triangle, already in AMD order: the factorization reads it in place (with
  // Eigen's own ordering it would copy a reordered matrix at every factorization).
  HessianPattern pattern;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Upper, Eigen::NaturalOrdering<int>> ldlt;
  Eigen::VectorXd rhs, solution;  // in the pattern's order
};

ImplicitEuler::ImplicitEuler(std::shared_ptr<const ClothModel> model, const NewtonSettings& options)
    : model_owner_(std::move(model)),
      model_(*model_owner_),
      options_(options),
      potential_(model_),
      hessian_(model_),
      pcg_(model_),
      x_(3 * model_.particle_count()),
      gradient_(3 * model_.particle_count()),
      dx_(3 * model_.particle_count()),
      trial_(3 * model_.particle_count()),
      rhs_(3 * model_.particle_count()) {
  if (options_.linear_solver == LinearSolverKind::direct) {
    direct_ = std::make_unique<DirectSolver>();
    direct_->pattern = build_hessian_pattern(model_, PatternLayout::upper_amd);
    direct_->rhs.resize(3 * model_.particle_count());
    direct_->solution.resize(3 * model_.particle_count());
    direct_->ldlt.analyzePattern(direct_->pattern.matrix);  // once: the pattern never changes
  }
  // The hierarchy's aggregates are built once per model_; each solve redoes its numbers.
  if (options_.linear_solver == LinearSolverKind::multigrid)
    multigrid_ = std::make_unique<MultigridPcg>(model_);
}

ImplicitEuler::~ImplicitEuler() = default;

bool ImplicitEuler::add_energy_term(std::shared_ptr<EnergyTerm> term) {
  potential_.add_term(std::move(term));
  return true;
}

bool ImplicitEuler::solve_newton_system(double relative_gradient, IterationRecord& record) {
  rhs_ = -gradient_;
  // The direct solver's pattern is the springs': a term coupling other particles is solved by
  // CG instead (same Newton direction, same stopping test), its diagonal blocks need not.
  const bool pattern_holds = std::all_of(hessian_.extra.begin(), hessian_.extra.end(),
                                         [](const HessianBlock& b) { return b.row == b.col; });
  if (direct_ && pattern_holds) {
    direct_->pattern.assign(hessian_);
    direct_->ldlt.factorize(direct_->pattern.matrix);
    const std::vector<int>& order = direct_->pattern.order;
    for (std::size_t i = 0; i < order.size(); ++i)
      direct_->rhs[order[i]] = rhs_[static_cast<Eigen::Index>(i)];
    direct_->solution = direct_->ldlt.solve(direct_->rhs);
    for (std::size_t i = 0; i < order.size(); ++i)
      dx_[static_cast<Eigen::Index>(i)] = direct_->solution[order[i]];
    // LDL^T of a symmetric matrix: positive definite exactly when every pivot is positive.
    return direct_->ldlt.info() == Eigen::Success && direct_->ldlt.vectorD().minCoeff() > 0.0;
  }
  // Inexact Newton (Eisenstat-Walker style): solve to a relative residual proportional to
  // the gradient's progress, 1% of it. Measured on the lab's cloth: tighter than the usual
  // sqrt-forcing, it saves a whole Newton iteration (Hessian, gradient, line search) per step
  // for a few extra CG iterations, which are cheaper: 2 Newton iterations per step instead of 3.
  // Never tighter than the step's own goal needs, though: near the tolerance, a residual of
  // half the remaining factor (tolerance / relative gradient) already stops Newton, and on
  // stiff cloth solving past it costs more CG iterations than the Newton iteration it saves.
  const double progress = 0.01 * std::clamp(relative_gradient, 1e-3, 0.5);
  const double goal = 0.5 * options_.tolerance / relative_gradient;
  double forcing = std::min(
      0.5, std::max(options_.linear_forcing > 0.0 ? options_.linear_forcing : progress, goal));
  const int max_cg = cg_iteration_cap(model_);
  const PcgResult pcg = multigrid_ ? multigrid_->solve(hessian_, rhs_, dx_, forcing, max_cg)
                                   : pcg_.solve(hessian_, rhs_, dx_, forcing, max_cg);
  record.linear_iterations += pcg.iterations;
  return !pcg.indefinite;
}

// The substep as a recipe of named stages (docs/implicit-step.md): start at the prediction,
// then Newton iterations (direction, step bound, line search, accept) until the stopping
// test, then the velocity update. Each stage adds its time to the report.
void ImplicitEuler::step(ClothState& state, double h, StepReport& report,
                         const Eigen::VectorXd* external_forces) {
  const auto substep_start = StageClock::now();
  const double start_norm = start_substep(state, h, external_forces, report);
  double gradient_norm = start_norm;
  const GradientStop stop =
      begin_implicit_substep(potential_, start_norm, options_.tolerance, report);
  // Converged: |grad g| small and every term at the substep's end (a moving collider at its
  // pose at t + h: until then g is not yet the end's potential).
  bool converged = stop.reached(gradient_norm) && potential_.terms_settled();
  const double speed_stop = options_.velocity_tolerance * bounding_diagonal(state.positions);
  report.speed_tolerance = speed_stop;
  ++report.friction_iterations;
  for (int k = 0; std::isfinite(gradient_norm) && k < options_.max_iterations; ++k) {
    // Converged: a term that lagged quantities may refresh them and go on (friction's passes).
    if (converged && !next_lagging_pass(stop, gradient_norm, report)) break;
    converged = false;
    if (stop.reached(gradient_norm)) {
      // x minimizes g with the terms where they are, but a term is short of the end: it moves
      // on from x (arrive_at_iterate updates the terms), then Newton resumes from there.
      gradient_norm = arrive_at_iterate(report);
      ++report.newton_iterations;
      converged = stop.reached(gradient_norm) && potential_.terms_settled();
      continue;
    }
    IterationRecord record;
    // g itself is needed only for the record: the line search works with differences.
    if (options_.record_iterations) record.objective = potential_.value(x_);
    double slope = newton_direction(gradient_norm, gradient_norm / start_norm, record, report);
    report.newton_speed_end = dx_.lpNorm<Eigen::Infinity>() / h;
    bool may_stop = report.newton_speed_end <= speed_stop;
    if (may_stop && options_.linear_forcing > kVerifyingForcing && record.linear_iterations > 0) {
      // CG solved it loosely: refine it, tighter, before ending on it.
      const std::optional<double> verified = verified_speed(h, record, report);
      may_stop = verified && *verified <= speed_stop;
      if (verified) report.newton_speed_end = *verified;
      slope = gradient_.dot(dx_);
    }
    if (may_stop && potential_.terms_settled() && potential_.terms_gaps_settled(x_, dx_)) {
      // The next correction is below the physical tolerance and no gap is closing: x is the
      // substep's end (IPC takes no step then either). Friction may re-lag at the loop's top.
      report.linear_iterations += record.linear_iterations;
      converged = true;
      continue;
    }
    const double bound = step_bound(report);
    const std::optional<double> decrease = line_search(slope, bound, record, report);
    report.line_search_steps += record.line_search_steps;
    report.linear_iterations += record.linear_iterations;
    if (!decrease) break;  // no decrease found: keep x (reported as not converged)
    gradient_norm = accept_step(report);
    ++report.newton_iterations;
    converged = stop.reached(gradient_norm) && potential_.terms_settled();

    record.gradient_norm = gradient_norm;
    record.ms = ms_since(substep_start);
    record.decrease = *decrease;
    if (options_.record_iterations) record.objective_after = potential_.value(x_);
    record.slope = slope;
    if (options_.record_iterations) report.iterations.push_back(record);
  }
  report.gradient_norm_end = gradient_norm;
  report.converged = report.converged && converged;
  finish_implicit_substep(model_, x_, h, state);
}

// Predict y, then start at y; with energy terms that bound steps (contact), at the admissible
// point of lowest g on the move from x_n to y instead (lowest_start; x_n itself is admissible:
// the previous substep ended there). Returns |grad g| there, the stopping test's reference.
double ImplicitEuler::start_substep(const ClothState& state, double h,
                                    const Eigen::VectorXd* external_forces, StepReport& report) {
  auto t = StageClock::now();
  potential_.prepare(state, h, external_forces);
  x_ = potential_.predicted();
  report.ms_gradient += ms_since(t);  // the prediction, counted with the gradient
  if (potential_.has_terms()) {
    t = StageClock::now();
    trial_ = x_ - state.positions;
    const double bound = potential_.max_step(state.positions, trial_);
    report.step_bound_min = std::min(report.step_bound_min, bound);
    if (bound < 1.0) x_ = state.positions + lowest_start(state.positions, bound) * trial_;
    report.ms_step_bound += ms_since(t);
  }
  return arrive_at_iterate(report);
}

// Where a substep starts when CCD cuts the move from x_n (`start`) to y (in trial_) short
// (bound < 1): of the admissible fractions bound, bound/2, ..., bound/16 and 0, the one of
// lowest g. Starting at the admissible end alone would put cloth resting on a surface, which
// the prediction pushes into it, at a tenth of its gap (CCD's minimum separation), and
// Newton's first iterations would only reopen that gap; x_n is where the last substep
// balanced the barrier. Measured on drape-sphere 41 x 41: resting steps take 4 Newton
// iterations instead of 7 or 8; on impact the end is still the lowest.
double ImplicitEuler::lowest_start(const Eigen::VectorXd& start, double bound) const {
  constexpr int kHalvings = 4;
  double best_fraction = 0.0, best = 0.0;  // t = 0: x_n, g's change 0
  double fraction = std::min(bound, 1.0);
  for (int k = 0; k <= kHalvings; ++k, fraction *= 0.5) {
    const double change = potential_.difference(start, fraction * trial_);
    if (change < best) {
      best = change;
      best_fraction = fraction;
    }
  }
  return best_fraction;
}

// At a converged x, terms with quantities lagged at x_n (friction's normal forces and bases)
// may re-lag there (IPC, Li et al. 2020, section 5). True when that broke the stopping test:
// Newton goes on from x with the re-lagged g (`gradient_norm` is its gradient there), one
// more lagging pass. False: nothing re-lagged, or x is still a minimum; the substep ends.
bool ImplicitEuler::next_lagging_pass(const GradientStop& stop, double& gradient_norm,
                                      StepReport& report) {
  if (!potential_.has_terms() || !potential_.relag_terms(x_)) return false;
  gradient_norm = arrive_at_iterate(report);
  if (stop.reached(gradient_norm)) return false;
  ++report.friction_iterations;
  return true;
}

// Hessian and Newton direction dx: the exact Hessian first unless always projecting; redone
// with the projected one (made from the exact one in place) when the solve meets negative
// curvature or gives no descent.
// Returns the slope grad g . dx < 0.
double ImplicitEuler::newton_direction(double gradient_norm, double relative_gradient,
                                       IterationRecord& record, StepReport& report) {
  bool projected = options_.projection == HessianProjection::always ||
                   (options_.projection == HessianProjection::with_terms && potential_.has_terms());
  double slope = 0.0;
  for (bool retry = false;; retry = true) {
    auto t = StageClock::now();
    if (retry)
      potential_.project_hessian(x_, hessian_);
    else
      potential_.hessian(x_, hessian_, projected);
    report.ms_hessian += ms_since(t);
    t = StageClock::now();
    const bool positive = solve_newton_system(relative_gradient, record);
    slope = gradient_.dot(dx_);
    report.ms_linear_solve += ms_since(t);
    if ((positive && slope < 0.0) || projected) break;
    projected = true;
  }
  record.projected = projected;
  report.projected_iterations += projected ? 1 : 0;
  if (!(slope < 0.0)) {
    // Only rounding can make the SPD system's solution ascend; steepest descent then.
    dx_ = -gradient_;
    slope = -gradient_norm * gradient_norm;
  }
  return slope;
}

// |dx|_inf / h of the Newton direction refined, with the same Hessian, to kVerifyingForcing
// (a direction solved loosely passed the velocity test); dx_ is then that direction. CG goes
// on from the loose direction with the same preconditioner rather than starting over: the
// residual it left is already a tenth of |grad g|. Should the tighter solve meet negative
// curvature or not descend, the loose direction stays and there is no verified speed. trial_
// is free until the line search.
std::optional<double> ImplicitEuler::verified_speed(double h, IterationRecord& record,
                                                    StepReport& report) {
  const auto t = StageClock::now();
  trial_ = dx_;
  const int max_cg = cg_iteration_cap(model_);
  const PcgResult pcg = multigrid_
                            ? multigrid_->refine(hessian_, rhs_, dx_, kVerifyingForcing, max_cg)
                            : pcg_.refine(hessian_, rhs_, dx_, kVerifyingForcing, max_cg);
  record.linear_iterations += pcg.iterations;
  const bool positive = !pcg.indefinite;
  report.ms_linear_solve += ms_since(t);
  if (positive && gradient_.dot(dx_) < 0.0) return dx_.lpNorm<Eigen::Infinity>() / h;
  dx_ = trial_;
  return std::nullopt;
}

// The longest fraction of dx the energy terms admit (continuous collision detection for
// contact); 1 without terms.
double ImplicitEuler::step_bound(StepReport& report) {
  if (!potential_.has_terms()) return 1.0;
  const auto t = StageClock::now();
  const double bound = potential_.max_step(x_, dx_);
  report.step_bound_min = std::min(report.step_bound_min, bound);
  report.ms_step_bound += ms_since(t);
  return bound;
}

// Backtracking line search (docs/implicit-step.md): alpha = 1/beta; repeat alpha = beta alpha,
// x' = x + alpha dx, until g(x') <= g(x) + gamma alpha grad.dx, starting no longer than the
// step bound. The difference g(x') - g(x) is evaluated directly (see
// IncrementalPotential::difference); a NaN or an infinity rejects. On success, trial_ holds
// the accepted step alpha dx and the decrease g(x') - g(x) is returned.
std::optional<double> ImplicitEuler::line_search(double slope, double bound,
                                                 IterationRecord& record, StepReport& report) {
  const auto t = StageClock::now();
  double alpha = std::min(1.0, bound) / options_.beta;
  double decrease = 0.0;
  bool accepted = false;
  for (int s = 0; s <= options_.max_line_search_steps && !accepted; ++s) {
    alpha *= options_.beta;
    trial_ = alpha * dx_;
    decrease = potential_.difference(x_, trial_);
    accepted = decrease <= options_.gamma * alpha * slope;
    record.line_search_steps = s;
  }
  if (accepted && record.projected && alpha == 1.0 && decrease <= 0.75 * slope) {
    extend_projected_step(decrease, alpha);
  }
  record.alpha = alpha;
  report.ms_line_search += ms_since(t);
  if (!accepted) return std::nullopt;
  return decrease;
}

// The projected Hessian drops the negative curvature of compressed springs, so where the
// cloth buckles its quadratic model is stiffer than g and the full step falls short: g then
// drops by nearly the whole linear prediction (a quadratic model predicts half). There,
// doubling the step while g keeps decreasing turns Newton's slow linear crawl through a
// buckling mode into a few long steps (still a descent: each doubling is kept only if g is
// lower, and only if the energy terms admit it).
void ImplicitEuler::extend_projected_step(double& decrease, double& alpha) {
  for (int e = 0; e < kMaxStepDoublings; ++e) {
    dx_ = 2.0 * trial_;
    if (potential_.has_terms() && potential_.max_step(x_, dx_) < 1.0) break;
    const double longer = potential_.difference(x_, dx_);
    if (!(longer < decrease)) break;
    decrease = longer;
    trial_.swap(dx_);
    alpha *= 2.0;
  }
}

// x += the accepted step; returns |grad g| there.
double ImplicitEuler::accept_step(StepReport& report) {
  x_ += trial_;
  return arrive_at_iterate(report);
}

// At a new iterate x: the terms move their world on (a collider, pushing x along), then see x
// (e.g. gather contact pairs), then grad g there; returns |grad g|.
double ImplicitEuler::arrive_at_iterate(StepReport& report) {
  auto t = StageClock::now();
  if (potential_.has_terms()) {
    potential_.advance_terms(x_);
    potential_.update_terms(x_);
    report.ms_term_updates += ms_since(t);
    t = StageClock::now();
  }
  potential_.gradient(x_, gradient_);
  report.ms_gradient += ms_since(t);
  return gradient_.norm();
}

}  // namespace animkit
