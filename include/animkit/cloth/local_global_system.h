#pragma once
// The constant matrix of the local/global method (Liu et al. 2013, "Fast simulation of
// mass-spring systems", eq. 10) for the whole incremental potential g, and its Cholesky factor.
// One N x N matrix (one row per particle) serves the x, y and z coordinates alike:
//   P(h) = S + C / h + M / h^2,
//   S = sum_springs k (e_a - e_b)(e_a - e_b)^T + sum_bends c w w^T   (w: the bend's weights)
//   C = sum_springs with a dashpot  c_damping (e_a - e_b)(e_a - e_b)^T,   M = diag(masses).
// P majorizes the Hessian of g everywhere: a spring's block is k [u u^T + t (I - u u^T)] with
// t = 1 - L/l < 1, so <= k I; a dashpot's is (c/h) u u^T <= (c/h) I; bends and inertia are
// quadratic and enter exactly. Pinned particles are eliminated: their row and column are the
// identity's, so a solve leaves their (zero) right-hand side entries alone.
//
// The fill-reducing ordering (AMD) and the symbolic analysis are done once per model; the
// numeric factorization once per time step size h (refactored only when h changes). On the
// 101 x 101 cotton grid METIS nested dissection gave no sparser factor than AMD (644k against
// 636k non-zeros in L) and CHOLMOD's own choice 655k, so animkit keeps Eigen's AMD and no new
// dependency.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "animkit/cloth/cloth_model.h"

namespace animkit {

/// The local/global method's constant matrix P(h) for one model, and its Cholesky factor.
class LocalGlobalSystem {
 public:
  /// Builds the pattern of P for `model` (kept by reference) and analyses it.
  explicit LocalGlobalSystem(const ClothModel& model);
  ~LocalGlobalSystem();

  /// Factorizes P(h) unless it already is factorized for this h. Returns whether it
  /// factorized (false: the factor of the previous call was kept).
  bool factorize(double h);
  /// The h (s) of the current factor; 0 before the first factorize().
  double factorized_h() const { return h_; }

  /// Solves P x = r for the three coordinates at once: `rhs` is 3N, particle-major (the
  /// solvers' layout), and is overwritten with the solution. Allocates nothing.
  void solve_in_place(Eigen::VectorXd& rhs);

  /// Non-zeros of the Cholesky factor L (diagonal included), to compare orderings.
  long factor_non_zeros() const;

 private:
  struct Factor;
  const ClothModel& model_;
  double h_ = 0.0;
  std::vector<int> order_;  // order_[i]: particle i's row in the permuted matrix
  // The three matrices of P(h) on one pattern (lower triangle, permuted), and P(h) itself.
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> stiffness_, damping_, mass_, matrix_;
  std::unique_ptr<Factor> factor_;
  Eigen::VectorXd permuted_;  // 3N, the right-hand side in the factor's order
};

}  // namespace animkit
