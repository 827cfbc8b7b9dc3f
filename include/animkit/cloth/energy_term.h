#pragma once
// An extra energy term of the implicit step's potential g (e.g. the contact barriers of issue
// 11, an attachment, a user's own force field): g(x) = inertia + springs + bends + dashpots +
// sum of terms. Newton's integrators take any term (ClothSimulator::add_energy_term); the
// others say why they cannot (see docs/stiff-cloth.md).
#include <Eigen/Core>
#include <string_view>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/step_report.h"

namespace animkit {

/// One 3x3 block of a term's Hessian, at particles (row, col). A block with row != col stands
/// for itself and its transpose at (col, row): terms list each off-diagonal pair once.
struct HessianBlock {
  /// Particle index of the block's rows.
  int row = 0, col = 0;                             ///< particle index of the block's columns
  Eigen::Matrix3d value = Eigen::Matrix3d::Zero();  ///< d^2 E / dx_row dx_col
};

/// An extra energy term E(x) of the implicit step's potential g, with the hooks Newton's
/// integrators call around each substep and iterate. Subclasses implement name(), value(),
/// add_gradient() and add_hessian(); the other hooks default to a term without moving parts.
class EnergyTerm {
 public:
  virtual ~EnergyTerm() = default;

  /// Names the term in messages ("floor contact").
  virtual std::string_view name() const = 0;
  /// Called at the start of every substep, from x_n (at time state.time) over h, before any
  /// evaluation (e.g. to gather contact pairs, freeze an axis, or aim a collider at its pose
  /// at state.time + h).
  virtual void prepare(const ClothState& /*state*/, double /*h*/) {}
  /// Called at every new iterate x of the minimization, before update(): a term whose world
  /// moves toward the substep's end (a collider) moves it there as far as it can, and may
  /// move x along with it (the cloth a collider pushes), keeping x admissible (by continuous
  /// collision detection) and pinned particles where they are. Default: nothing moves.
  virtual void advance(Eigen::VectorXd& /*x*/) {}
  /// Called at every new iterate x of the minimization (the starting point, then each
  /// accepted step) before g's gradient and Hessian are taken there: e.g. to gather the contact
  /// pairs close to x.
  virtual void update(const Eigen::VectorXd& /*x*/) {}
  /// Called when the minimization has converged at x: a term that froze quantities at x_n
  /// (friction's normal forces and tangent bases, IPC section 5) may refresh them from x and
  /// return true; the minimization then goes on from x with the changed g. False: nothing
  /// changed (the default), the substep ends.
  virtual bool relag(const Eigen::VectorXd& /*x*/) { return false; }
  /// Whether the term has reached the substep's end (e.g. every moving collider at its pose
  /// at t + h). A term whose own parameters move toward the end as the minimization goes
  /// (update() advancing a collider only as far as CCD allows) says false until they are
  /// there: the solver does not report convergence before every term is settled, and keeps
  /// calling update() at its iterate. Default: always settled.
  virtual bool settled() const { return true; }
  /// Whether the term is at rest at x along Newton's next correction `dx`, so that a substep
  /// may end there on the test of the correction's size alone
  /// (NewtonSettings::velocity_tolerance). A barrier's Newton correction at a small gap is
  /// never much larger than the gap itself, so a small correction alone does not show that a
  /// squeezed gap (a substep starts at the admissible point of lowest g, which may close a
  /// resting gap to a tenth) has reopened: contact wants no vertex of a close pair to move by
  /// more than a fraction of the pair's distance. Default: yes.
  virtual bool gaps_settled(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*dx*/) const {
    return true;
  }
  /// The largest fraction t in (0, 1] of `step` such that every point x + s step, s in [0, t],
  /// is admissible for this term (e.g. intersection-free, by conservative continuous collision
  /// detection); the line search never tries a longer step. Called once per iteration before
  /// the line search: the term may then prepare to evaluate anywhere on that segment (e.g.
  /// gather the pairs the motion sweeps past). Every term without a barrier admits any step.
  virtual double max_step(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*step*/) {
    return 1.0;
  }
  /// After each step, at the new positions: adds the term's own numbers to the step's report
  /// (e.g. contact counts and the smallest distance).
  virtual void add_to_report(const Eigen::VectorXd& /*x*/, StepReport& /*report*/) const {}
  /// E(x); +infinity where x is not admissible.
  virtual double value(const Eigen::VectorXd& x) const = 0;
  /// E(x + step) - E(x). The line search compares differences; the default subtracts two
  /// values (and allocates), which loses small decreases when E is large: override it with a
  /// cancellation-free form where that matters.
  virtual double difference(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const {
    const Eigen::VectorXd moved = x + step;
    return value(moved) - value(x);
  }
  /// gradient += grad E(x) (3N; entries of pinned particles are discarded by the caller).
  virtual void add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const = 0;
  /// Appends the Hessian of E at x as 3x3 blocks. `projected`: each block set must then be
  /// positive semidefinite as a whole (Newton's fallback when the exact Hessian is indefinite).
  virtual void add_hessian(const Eigen::VectorXd& x, bool projected,
                           std::vector<HessianBlock>& blocks) const = 0;
  /// True when add_hessian appends the same blocks, to the bit, whether `projected` or not
  /// (they are PSD as they are): Newton's projected retry then keeps this term's blocks from
  /// the exact attempt instead of recomputing them.
  virtual bool hessian_ignores_projection() const { return false; }
};

}  // namespace animkit
