#pragma once
// Preconditioned conjugate gradients on the block Hessian (matrix-free: it is applied spring
// by spring), with the inverses of its 3x3 diagonal blocks as preconditioner (one block per
// particle: each particle's mass and the stiffness of its springs in every direction).
// Workspace sized once.
#include <Eigen/Core>
#include <vector>

#include "animkit/cloth/block_hessian.h"

namespace animkit {

struct PcgResult {
  int iterations = 0;
  double relative_residual = 0.0;  ///< |b - A x| / |b| at exit
  bool converged = false;
  /// The matrix showed a direction of non-positive curvature (p.Ap <= 0): it is not positive
  /// definite. The solve stops there; x holds the last iterate (a descent direction for any
  /// SPD part met so far).
  bool indefinite = false;
};

class BlockJacobiPcg {
 public:
  explicit BlockJacobiPcg(const ClothModel& model);

  /// Solves A x = b for the symmetric matrix in `a`, from x = 0, until |b - A x| <= tolerance
  /// |b|, `max_iterations`, or a direction of non-positive curvature (see PcgResult).
  PcgResult solve(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  double tolerance, int max_iterations);

 private:
  void apply_preconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z) const;

  const ClothModel& model_;
  std::vector<Eigen::Matrix3d> inverse_blocks_;
  Eigen::VectorXd r_, z_, p_, ap_;
};

}  // namespace animkit
