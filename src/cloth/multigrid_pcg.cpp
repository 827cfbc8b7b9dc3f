#include "animkit/cloth/multigrid_pcg.h"

#include "smoothed_aggregation.h"

namespace animkit {

MultigridPcg::MultigridPcg(const ClothModel& model, const MultigridOptions& options)
    : model_(model),
      multigrid_(std::make_unique<SmoothedAggregation>(model, options)),
      workspace_(model.particle_count()) {}

MultigridPcg::~MultigridPcg() = default;

int MultigridPcg::level_count() const {
  return multigrid_->level_count();
}

int MultigridPcg::level_nodes(int level) const {
  return multigrid_->level_nodes(level);
}

int MultigridPcg::level_blocks(int level) const {
  return multigrid_->level_blocks(level);
}

void MultigridPcg::apply_preconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  multigrid_->apply(r, z);
}

PcgResult MultigridPcg::solve(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                              double tolerance, int max_iterations) {
  if (!multigrid_->update(a)) {
    PcgResult result;
    result.indefinite = true;
    result.relative_residual = 1.0;
    return result;
  }
  return iterate(a, b, x, tolerance, max_iterations, CgStart::zero);
}

PcgResult MultigridPcg::refine(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                               double tolerance, int max_iterations) {
  return iterate(a, b, x, tolerance, max_iterations, CgStart::given);
}

PcgResult MultigridPcg::iterate(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                double tolerance, int max_iterations, CgStart start) {
  // The V-cycle is SPD when A is; for an indefinite A (the exact Hessian) CG reports it. The
  // products take the energy terms' blocks as the hierarchy assembled them (add_term_products).
  return preconditioned_cg(
      [&](const Eigen::VectorXd& p, Eigen::VectorXd& ap) {
        a.multiply_without_terms(model_, p, ap);
        multigrid_->add_term_products(p, ap);
      },
      b, x, tolerance, max_iterations,
      [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { multigrid_->apply(r, z); }, workspace_,
      start);
}

}  // namespace animkit
