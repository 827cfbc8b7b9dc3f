#pragma once
// Preconditioned conjugate gradients on the block Hessian (matrix-free: BlockHessian::multiply),
// shared by every preconditioner (block Jacobi, smoothed aggregation multigrid) so they stop and
// report the same way.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <vector>

#include "animkit/cloth/block_hessian.h"

namespace animkit {

/// How a preconditioned CG solve ended.
struct PcgResult {
  int iterations = 0;              ///< CG iterations done, one product with A each
  double relative_residual = 0.0;  ///< |b - A x| / |b| at exit
  bool converged = false;          ///< |b - A x| <= tolerance |b| at exit (true at once for b = 0)
  /// The matrix showed a direction of non-positive curvature (p.Ap <= 0), or the preconditioned
  /// residual r.z was not positive: A (or its preconditioner) is not positive definite. The
  /// solve stops there; x holds the last iterate (a descent direction for any SPD part met).
  bool indefinite = false;
};

/// CG's vectors and its sums' chunk workspace, sized once per model so a solve allocates
/// nothing.
struct CgWorkspace {
  /// Sizes the vectors for `particles` particles (3 entries each) and one partial sum per chunk
  /// of them.
  explicit CgWorkspace(int particles);
  /// Residual b - A x (3N).
  Eigen::VectorXd r, z, p, ap;                  ///< A p (3N)
  std::vector<std::array<double, 1>> partials;  ///< per-chunk partial sums of the dot products
  /// \var z
  /// Preconditioned residual B r (3N).
  /// \var p
  /// Search direction (3N).
};

/// z = B r for an SPD B ~ A^-1.
using Preconditioner = std::function<void(const Eigen::VectorXd& r, Eigen::VectorXd& z)>;

/// y = A x.
using LinearOperator = std::function<void(const Eigen::VectorXd& x, Eigen::VectorXd& y)>;

/// Where a CG solve starts.
enum class CgStart {
  zero,  ///< x = 0
  /// The x passed in, an earlier solve's answer to be refined: CG goes on from its residual
  /// b - A x (one more product with A) and stops at once if that already meets the tolerance.
  given,
};

/// Solves A x = b from x = 0 (or from x, see CgStart) until |b - A x| <= tolerance |b|,
/// `max_iterations`, or a sign that A is not positive definite. Its vector operations run on
/// the library's threads, with sums over fixed chunks: the same bits for any thread count.
PcgResult preconditioned_cg(const LinearOperator& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                            double tolerance, int max_iterations,
                            const Preconditioner& precondition, CgWorkspace& w,
                            CgStart start = CgStart::zero);
/// The same with A the Newton system's blocks (BlockHessian::multiply).
PcgResult preconditioned_cg(const ClothModel& model, const BlockHessian& a,
                            const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                            int max_iterations, const Preconditioner& precondition, CgWorkspace& w,
                            CgStart start = CgStart::zero);

}  // namespace animkit
