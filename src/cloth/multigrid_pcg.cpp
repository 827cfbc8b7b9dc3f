#include "animkit/cloth/multigrid_pcg.h"

#include "smoothed_aggregation.h"

namespace animkit {

MultigridPcg::MultigridPcg(const ClothModel& model, const MultigridOptions& options)
    : model_(model),
      multigrid_(std::make_unique<SmoothedAggregation>(model, options)),
      r_(3 * model.particle_count()),
      z_(3 * model.particle_count()),
      p_(3 * model.particle_count()),
      ap_(3 * model.particle_count()) {}

MultigridPcg::~MultigridPcg() = default;

int MultigridPcg::level_count() const {
  return multigrid_->level_count();
}

int MultigridPcg::level_nodes(int level) const {
  return multigrid_->level_nodes(level);
}

void MultigridPcg::apply_preconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  multigrid_->apply(r, z);
}

PcgResult MultigridPcg::solve(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                              double tolerance, int max_iterations) {
  PcgResult result;
  x.setZero();
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    result.converged = true;
    return result;
  }
  if (!multigrid_->update(a)) {
    result.indefinite = true;
    result.relative_residual = 1.0;
    return result;
  }
  r_ = b;
  const double threshold = tolerance * b_norm;
  multigrid_->apply(r_, z_);
  p_ = z_;
  double rz = r_.dot(z_);
  double r_norm = b_norm;
  // The V-cycle is SPD when A is; an indefinite A (the exact Hessian) can make r.z <= 0, which
  // is reported like negative curvature, so the caller projects.
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
    multigrid_->apply(r_, z_);
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
