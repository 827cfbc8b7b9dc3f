#pragma once
// Preconditioned conjugate gradients on the block Hessian (matrix-free: BlockHessian::multiply),
// shared by every preconditioner (block Jacobi, smoothed aggregation multigrid) so they stop and
// report the same way.
#include <Eigen/Core>

#include "animkit/cloth/block_hessian.h"

namespace animkit {

struct PcgResult {
  int iterations = 0;
  double relative_residual = 0.0;  ///< |b - A x| / |b| at exit
  bool converged = false;
  /// The matrix showed a direction of non-positive curvature (p.Ap <= 0), or the preconditioned
  /// residual r.z was not positive: A (or its preconditioner) is not positive definite. The
  /// solve stops there; x holds the last iterate (a descent direction for any SPD part met).
  bool indefinite = false;
};

/// CG's vectors, sized once per model so a solve allocates nothing.
struct CgWorkspace {
  explicit CgWorkspace(Eigen::Index size) : r(size), z(size), p(size), ap(size) {}
  Eigen::VectorXd r, z, p, ap;
};

/// Solves A x = b from x = 0 until |b - A x| <= tolerance |b|, `max_iterations`, or a sign that
/// A is not positive definite. `precondition(r, z)` writes z = B r for an SPD B ~ A^-1.
template <class Preconditioner>
PcgResult preconditioned_cg(const ClothModel& model, const BlockHessian& a,
                            const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                            int max_iterations, Preconditioner&& precondition, CgWorkspace& w) {
  PcgResult result;
  x.setZero();
  const double b_norm = b.norm();
  if (b_norm == 0.0) {
    result.converged = true;
    return result;
  }
  w.r = b;
  const double threshold = tolerance * b_norm;
  precondition(w.r, w.z);
  w.p = w.z;
  double rz = w.r.dot(w.z);
  double r_norm = b_norm;
  // With the exact Hessian the preconditioner itself can be indefinite; then r.z may be <= 0
  // and CG has no meaning: report it like negative curvature, so the caller projects.
  if (!(rz > 0.0)) {
    result.indefinite = true;
    result.relative_residual = 1.0;
    return result;
  }
  while (result.iterations < max_iterations) {
    a.multiply(model, w.p, w.ap);
    const double curvature = w.p.dot(w.ap);
    if (!(curvature > 0.0)) {
      result.indefinite = true;
      break;
    }
    const double alpha = rz / curvature;
    x.noalias() += alpha * w.p;
    w.r.noalias() -= alpha * w.ap;
    ++result.iterations;
    r_norm = w.r.norm();
    if (r_norm <= threshold) break;
    precondition(w.r, w.z);
    const double rz_next = w.r.dot(w.z);
    if (!(rz_next > 0.0)) {
      result.indefinite = true;
      break;
    }
    w.p = w.z + (rz_next / rz) * w.p;
    rz = rz_next;
  }
  result.relative_residual = r_norm / b_norm;
  result.converged = r_norm <= threshold;
  return result;
}

}  // namespace animkit
