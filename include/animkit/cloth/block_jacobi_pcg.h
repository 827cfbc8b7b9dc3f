#pragma once
// Preconditioned conjugate gradients (preconditioned_cg.h) with the inverses of its 3x3 diagonal
// blocks as preconditioner (one block per particle: each particle's mass and the stiffness of its
// springs in every direction). Workspace sized once.
#include <Eigen/Core>
#include <vector>

#include "animkit/cloth/block_hessian.h"
#include "animkit/cloth/preconditioned_cg.h"

namespace animkit {

/// Conjugate gradients preconditioned by the inverses of the matrix's 3x3 diagonal blocks.
class BlockJacobiPcg {
 public:
  /// Sizes the workspace for `model` (kept by reference: it must outlive this).
  explicit BlockJacobiPcg(const ClothModel& model);

  /// Solves A x = b for the symmetric matrix in `a`, from x = 0, until |b - A x| <= tolerance
  /// |b|, `max_iterations`, or a direction of non-positive curvature (see PcgResult).
  PcgResult solve(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  double tolerance, int max_iterations);
  /// Refines the last solve's answer x of A x = b to the tighter `tolerance`, going on from x
  /// with the inverse blocks that solve computed: `a` and `b` must be the same as then.
  PcgResult refine(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   double tolerance, int max_iterations);

 private:
  void apply_preconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

  const ClothModel& model_;
  std::vector<Eigen::Matrix3d> inverse_blocks_;
  CgWorkspace workspace_;
};

}  // namespace animkit
