#include "animkit/cloth/block_hessian.h"

#include <atomic>

#include "../core/parallel.h"

namespace animkit {

void BlockHessian::renew_terms_revision() {
  static std::atomic<std::uint64_t> last{0};
  terms_revision = ++last;
}

void BlockHessian::multiply(const ClothModel& model, const Eigen::VectorXd& p,
                            Eigen::VectorXd& y) const {
  multiply_without_terms(model, p, y);
  for (const HessianBlock& block : extra) {  // both ends free (see IncrementalPotential)
    y.segment<3>(3 * block.row).noalias() += block.value * p.segment<3>(3 * block.col);
    if (block.row != block.col) {
      y.segment<3>(3 * block.col).noalias() +=
          block.value.transpose() * p.segment<3>(3 * block.row);
    }
  }
}

void BlockHessian::multiply_without_terms(const ClothModel& model, const Eigen::VectorXd& p,
                                          Eigen::VectorXd& y) const {
  // A p = (M / h^2) p + sum over springs of [K -K; -K K] (p_a, p_b): one 3x3 product per
  // spring, K (p_a - p_b), added to a and subtracted from b, instead of a product per block.
  parallel::for_each(static_cast<int>(inertia.size()), [&](int i) {
    const auto k = static_cast<Eigen::Index>(3 * i);
    y.segment<3>(k) = inertia[i] * p.segment<3>(k);
  });
  parallel::scatter(springs, [&](int s) {
    const auto [a, b] = model.springs[s];
    const bool free_a = !model.pinned[a], free_b = !model.pinned[b];
    // A pinned end is not an unknown: its p entries are zero and its row stays the identity's.
    const Eigen::Vector3d d =
        (free_a ? Eigen::Vector3d(p.segment<3>(3 * a)) : Eigen::Vector3d::Zero()) -
        (free_b ? Eigen::Vector3d(p.segment<3>(3 * b)) : Eigen::Vector3d::Zero());
    const Eigen::Vector3d kd = coupling[s] * d;
    if (free_a) y.segment<3>(3 * a) += kd;
    if (free_b) y.segment<3>(3 * b) -= kd;
  });
}

}  // namespace animkit
