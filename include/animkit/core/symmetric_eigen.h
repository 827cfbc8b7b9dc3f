#pragma once
// The eigendecomposition of a symmetric matrix, A = U diag(lambda) U^T, that allocates nothing
// once it has seen a matrix of the same size. Eigen's SelfAdjointEigenSolver::compute()
// allocates a scratch vector on every call (to form the Householder reflections' product);
// this does the same three steps (Householder tridiagonalization, the reflections' product,
// implicit symmetric QR on the tridiagonal matrix) with that scratch kept here. Used by SDLS
// (dls_tree.h) in every iteration, where the solver promises no allocation per call.
#include <Eigen/Dense>

namespace animkit {

/// Eigendecomposition A = U diag(lambda) U^T of a symmetric matrix that reuses its scratch
/// storage, so repeated compute() calls on same-sized matrices do not allocate.
class SymmetricEigen {
 public:
  /// Decomposes the symmetric `a` (its lower triangle is read). Eigenvalues ascending.
  void compute(const Eigen::MatrixXd& a);

  /// The eigenvalues of the last compute(), in ascending order.
  const Eigen::VectorXd& eigenvalues() const { return eigenvalues_; }
  /// Column i is the unit eigenvector of eigenvalues()[i].
  const Eigen::MatrixXd& eigenvectors() const { return eigenvectors_; }

 private:
  Eigen::MatrixXd reduced_;      // the tridiagonalization, reflections below the subdiagonal
  Eigen::VectorXd householder_;  // the reflections' coefficients
  Eigen::MatrixXd reflections_;  // Q, the reflections' product: a = Q T Q^T
  Eigen::VectorXd scratch_;      // what Eigen would allocate to form Q
  Eigen::VectorXd diagonal_;     // T's diagonal
  Eigen::VectorXd subdiagonal_;  // T's subdiagonal
  // T = Z diag(lambda) Z^T. Computed once at construction so that a fresh SymmetricEigen can be
  // copied or moved (a solver that never computed holds an uninitialized status).
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> tridiagonal_{Eigen::MatrixXd::Identity(1, 1)};
  Eigen::VectorXd eigenvalues_;
  Eigen::MatrixXd eigenvectors_;  // U = Q Z
};

}  // namespace animkit
