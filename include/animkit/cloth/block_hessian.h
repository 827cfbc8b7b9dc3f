#pragma once
// The implicit step's Hessian stored by blocks, the form matrix-free solvers use: per particle
// its mass term and its full 3x3 diagonal block, per spring the 3x3 block K its two particles
// share (the matrix holds +K in both diagonal blocks and -K at (a, b) and (b, a)). Building it
// writes the arrays in order; multiplying by it reads them in the order of an ElementSchedule,
// which lets threads share the springs with the same bits as one thread.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/element_schedule.h"
#include "animkit/cloth/energy_term.h"

namespace animkit {

/// The implicit step's Hessian stored by 3x3 blocks, for the matrix-free linear solvers.
struct BlockHessian {
  std::vector<Eigen::Matrix3d> diagonal;  ///< per particle, all terms (identity when pinned)
  std::vector<double> inertia;            ///< per particle: m / h^2 (1 when pinned)
  std::vector<Eigen::Matrix3d> coupling;  ///< per spring: K
  /// The extra energy terms' blocks between free particles (see energy_term.h); empty without
  /// terms. Their diagonal blocks are also added into `diagonal`, which is all preconditioners
  /// see of them; the products, and so CG's answer, include them all.
  std::vector<HessianBlock> extra;
  /// Names what `extra` holds: a new value, never seen before in this process, each time it is
  /// refilled (renew_terms_revision), kept while only the springs' blocks change (Newton's
  /// projected retry). The multigrid keeps what it built from `extra` while the revision is the
  /// one it saw last, products included: whoever changes `extra` must renew it (a copy keeps
  /// it too). 0, a Hessian never named: nothing is kept.
  std::uint64_t terms_revision = 0;
  ElementSchedule springs;  ///< the model's springs, for the products

  /// Sizes the arrays for `model`'s particles and springs (the step that builds the Hessian
  /// fills them) and builds the spring schedule.
  explicit BlockHessian(const ClothModel& model)
      : diagonal(model.particle_count()),
        inertia(model.particle_count()),
        coupling(model.springs.size()),
        springs(model.springs, model.particle_count()) {}

  /// Gives `extra` a new terms_revision.
  void renew_terms_revision();
  /// y = A p for the model's springs. A pinned particle's row is the identity's, and a spring
  /// touching it acts on the free end only.
  void multiply(const ClothModel& model, const Eigen::VectorXd& p, Eigen::VectorXd& y) const;
  /// y = (M / h^2 + the springs' blocks) p: multiply() without the energy terms' `extra`.
  void multiply_without_terms(const ClothModel& model, const Eigen::VectorXd& p,
                              Eigen::VectorXd& y) const;
};

}  // namespace animkit
