#include "animkit/cloth/block_jacobi_pcg.h"

#include <cmath>

namespace animkit {

BlockJacobiPcg::BlockJacobiPcg(const ClothModel& model)
    : model_(model),
      inverse_blocks_(model.particle_count()),
      r_(3 * model.particle_count()),
      z_(3 * model.particle_count()),
      p_(3 * model.particle_count()),
      ap_(3 * model.particle_count()) {}

void BlockJacobiPcg::apply_preconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  for (std::size_t i = 0; i < inverse_blocks_.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(3 * i);
    z.segment<3>(k).noalias() = inverse_blocks_[i] * r.segment<3>(k);
  }
}

PcgResult BlockJacobiPcg::solve(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                double tolerance, int max_iterations) {
  for (std::size_t i = 0; i < inverse_blocks_.size(); ++i) {
    const Eigen::Matrix3d& block = a.diagonal[i];
    // Mass / h^2 dominates each diagonal block, so it is invertible even with the exact
    // Hessian; should it not be, fall back to the inverse of its diagonal's magnitude.
    bool invertible = false;
    block.computeInverseWithCheck(inverse_blocks_[i], invertible);
    if (!invertible)
      inverse_blocks_[i] = block.diagonal().cwiseAbs().cwiseMax(1e-300).cwiseInverse().asDiagonal();
  }
  PcgResult result;
  x.setZero();
  r_ = b;
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    result.converged = true;
    return result;
  }
  const double threshold = tolerance * b_norm;
  apply_preconditioner(r_, z_);
  p_ = z_;
  double rz = r_.dot(z_);
  double r_norm = b_norm;
  // With the exact Hessian a diagonal block can itself be indefinite; then r.z may be <= 0 and
  // CG has no meaning: report it like negative curvature, so the caller projects.
  if (!(rz > 0.0)) {
    result.indefinite = true;
    return result;
  }
  while (result.iterations < max_iterations) {
    a.multiply(model_, p_, ap_);
    const double curvature = p_.dot(ap_);
    if (!(curvature > 0.0)) {
      result.indefinite = true;
      break;
    }
    const double alpha = rz / curvature;
    x.noalias() += alpha * p_;
    r_.noalias() -= alpha * ap_;
    ++result.iterations;
    r_norm = r_.norm();
    if (r_norm <= threshold) break;
    apply_preconditioner(r_, z_);
    const double rz_next = r_.dot(z_);
    if (!(rz_next > 0.0)) {
      result.indefinite = true;
      break;
    }
    p_ = z_ + (rz_next / rz) * p_;
    rz = rz_next;
  }
  result.relative_residual = r_norm / b_norm;
  result.converged = r_norm <= threshold;
  return result;
}

}  // namespace animkit
