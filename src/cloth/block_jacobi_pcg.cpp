#include "animkit/cloth/block_jacobi_pcg.h"

#include <cmath>

#include "../core/parallel.h"

namespace animkit {

BlockJacobiPcg::BlockJacobiPcg(const ClothModel& model)
    : model_(model), inverse_blocks_(model.particle_count()), workspace_(model.particle_count()) {}

void BlockJacobiPcg::apply_preconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  parallel::for_each(static_cast<int>(inverse_blocks_.size()), [&](int i) {
    z.segment<3>(3 * i).noalias() = inverse_blocks_[i] * r.segment<3>(3 * i);
  });
}

PcgResult BlockJacobiPcg::solve(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                double tolerance, int max_iterations) {
  parallel::for_each(static_cast<int>(inverse_blocks_.size()), [&](int i) {
    const Eigen::Matrix3d& block = a.diagonal[i];
    // Mass / h^2 dominates each diagonal block, so it is invertible even with the exact
    // Hessian; should it not be, fall back to the inverse of its diagonal's magnitude.
    bool invertible = false;
    block.computeInverseWithCheck(inverse_blocks_[i], invertible);
    if (!invertible)
      inverse_blocks_[i] = block.diagonal().cwiseAbs().cwiseMax(1e-300).cwiseInverse().asDiagonal();
  });
  return preconditioned_cg(
      model_, a, b, x, tolerance, max_iterations,
      [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { apply_preconditioner(r, z); },
      workspace_);
}

PcgResult BlockJacobiPcg::refine(const BlockHessian& a, const Eigen::VectorXd& b,
                                 Eigen::VectorXd& x, double tolerance, int max_iterations) {
  return preconditioned_cg(
      model_, a, b, x, tolerance, max_iterations,
      [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { apply_preconditioner(r, z); },
      workspace_, CgStart::given);
}

}  // namespace animkit
