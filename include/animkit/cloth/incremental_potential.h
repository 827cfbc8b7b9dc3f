#pragma once
// Implicit Euler as energy minimization (docs/implicit-step.md). With h the step, M the masses,
// x_n, v_n the state at the step's start and f_ext = M g the gravity:
//   y    = x_n + h v_n + h^2 M^-1 f_ext
//   g(x) = 1/(2h^2) |x - y|_M^2 + E(x) + D(x)
//   grad g = M (x - y) / h^2 + grad E(x) + grad D(x),
//   Hessian = M / h^2 + H(x) + (c / h) sum_springs [u u^T -u u^T; -u u^T u u^T]
// E is the springs' elastic energy. D adds the lab's spring dashpots (force -c ((v_a - v_b).u) u
// on a) implicitly: with v = (x - x_n) / h and each axis u frozen at x_n,
//   D(x) = c / (2h) sum_springs ((dx_a - dx_b) . u)^2,   dx = x - x_n,
// a convex quadratic, so the step stays stable (and dissipative) at any h. Extra energy terms
// (energy_term.h) add to g, its gradient and Hessian. Pinned particles are not unknowns: their
// gradient entries are zero and they stay at x_n.
//
// Every loop is split over threads (src/core/parallel.h) with results independent of the
// thread count: springs and bends add into their particles in the order of an
// ElementSchedule, and sums are taken over fixed chunks. The chunk sums' workspace makes the
// const methods unsafe to call on one object from two threads at once.
#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "animkit/cloth/block_hessian.h"
#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/element_schedule.h"
#include "animkit/cloth/energy_term.h"

namespace animkit {

/// The incremental potential g of an implicit Euler step (see the comment at the top of
/// incremental_potential.h), with its extra energy terms: value, differences, gradient and Hessian.
class IncrementalPotential {
 public:
  /// Sizes the workspace for `model` (kept by reference: it must outlive this object).
  explicit IncrementalPotential(const ClothModel& model);

  /// Adds an energy term to g (kept and shared: the caller may keep changing its parameters).
  void add_term(std::shared_ptr<EnergyTerm> term) { terms_.push_back(std::move(term)); }
  /// The added energy terms, in the order added.
  const std::vector<std::shared_ptr<EnergyTerm>>& terms() const { return terms_; }

  /// Sets up the step from `state` over time h > 0: y, x_n and the damping axes.
  /// `external_forces` (3N, world units; may be null) act like gravity: constant over the step,
  /// they enter y as h^2 M^-1 f (e.g. the viewer's mouse spring, evaluated at x_n).
  void prepare(const ClothState& state, double h, const Eigen::VectorXd* external_forces = nullptr);

  /// Lets every term move its world toward the substep's end, and x with it
  /// (EnergyTerm::advance).
  void advance_terms(Eigen::VectorXd& x);
  /// Tells every term that the minimization reached x (see EnergyTerm::update).
  void update_terms(const Eigen::VectorXd& x);
  /// Lets every term re-lag at a converged x (EnergyTerm::relag); true if any changed g.
  bool relag_terms(const Eigen::VectorXd& x);
  /// The largest fraction in (0, 1] of `step` every term admits from x (EnergyTerm::max_step);
  /// 1 without terms.
  double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& step);
  /// Whether every term has reached the substep's end (EnergyTerm::settled).
  bool terms_settled() const;
  /// Every term's EnergyTerm::gaps_settled at x along dx.
  bool terms_gaps_settled(const Eigen::VectorXd& x, const Eigen::VectorXd& dx) const;
  /// Whether any term may bound the step (then the minimization starts from an admissible point
  /// between x_n and y instead of from y itself).
  bool has_terms() const { return !terms_.empty(); }

  /// The predicted positions y, where Newton starts (pinned particles: x_n).
  const Eigen::VectorXd& predicted() const { return y_; }

  /// x_n, the step's start (from prepare()).
  const Eigen::VectorXd& start() const { return x_start_; }
  /// The step h (s), from prepare().
  double time_step() const { return h_; }
  /// Per spring, its dashpot's unit axis frozen at x_n (zero: no dashpot).
  const std::vector<Vec3>& damping_axes() const { return damping_axis_; }

  /// The gradient norm below which |grad g| is rounding noise that no solver can shrink: every
  /// solver's stopping test is max(tolerance |grad g(y)|, this). The gradient sums the inertia
  /// term M (x - y) / h^2 and spring forces k (l - L) u, each computed from coordinates with a
  /// relative rounding of a few eps, so the floor is 16 eps (|M y| / h^2 + |(k L) over springs|).
  double gradient_floor() const { return gradient_floor_; }

  /// g(x).
  double value(const Eigen::VectorXd& x) const;
  /// g(x + step) - g(x), computed term by term in forms free of cancellation (e.g.
  /// |a + s|^2 - |a|^2 = s.(2a + s)), so it resolves decreases far below the rounding error of
  /// g itself. The line search compares this, not two values of g: near the solution Newton's
  /// decreases are smaller than g's last bits, and comparing values would stall there.
  double difference(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const;
  /// grad g(x) into `gradient` (sized 3N; pinned entries zero).
  void gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const;
  /// The Hessian of g at x, by blocks. `projected` keeps each spring block positive
  /// semidefinite (see spring_energy.h), so the matrix is SPD; the exact one may be indefinite
  /// where springs are compressed.
  void hessian(const Eigen::VectorXd& x, BlockHessian& blocks, bool projected) const;
  /// `blocks`, holding this potential's hessian(x, blocks, false), made the projected Hessian at
  /// the same x. When no term's blocks depend on the projection
  /// (EnergyTerm::hessian_ignores_projection), only the springs' blocks are redone, the terms'
  /// blocks and their BlockHessian::terms_revision kept (the same bits as hessian(x, blocks,
  /// true)); otherwise all of it, under a new revision.
  void project_hessian(const Eigen::VectorXd& x, BlockHessian& blocks) const;

 private:
  const ClothModel& model_;
  double h_ = 0.0;
  double spring_force_scale_ = 0.0;  // |(k L) over springs|
  double gradient_floor_ = 0.0;
  Eigen::VectorXd y_, x_start_;
  std::vector<Vec3> damping_axis_;  // per spring: unit axis at x_n (zero if degenerate)
  std::vector<std::shared_ptr<EnergyTerm>> terms_;
  mutable std::vector<HessianBlock> term_blocks_;  // scratch of hessian(), kept for its capacity

  void spring_hessian(const Eigen::VectorXd& x, BlockHessian& blocks, bool projected) const;
  void add_term_hessians(const Eigen::VectorXd& x, BlockHessian& blocks, bool projected) const;
  ElementSchedule spring_schedule_, bend_schedule_;
  std::vector<double> bend_coupling_;  // per spring: the bends' constant K (times I), summed
  mutable std::vector<std::array<double, 2>> partials_;  // chunk sums (parallel::sum)
};

}  // namespace animkit
