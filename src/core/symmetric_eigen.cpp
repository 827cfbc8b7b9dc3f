// GCC 12's own AVX-512 intrinsics trip -Wuninitialized when Eigen's dense decompositions are
// inlined with -march=native at -O1 (the sanitizer build): a false positive in the compiler's
// headers (see psd_projection.cpp), silenced for this file only.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "animkit/core/symmetric_eigen.h"

namespace animkit {

void SymmetricEigen::compute(const Eigen::MatrixXd& a) {
  const Eigen::Index n = a.rows();
  if (n < 2) {  // nothing to reduce; Householder sequences need n >= 2
    eigenvalues_ = a.diagonal();
    eigenvectors_.setIdentity(n, n);
    return;
  }
  // Scaled into [-1, 1] against over- and underflow, as Eigen's compute() does.
  reduced_ = a.triangularView<Eigen::Lower>();
  double scale = reduced_.cwiseAbs().maxCoeff();
  if (scale == 0.0) scale = 1.0;
  reduced_ /= scale;
  householder_.resize(n - 1);
  // Eigen's own step (what SelfAdjointEigenSolver::compute() calls): reduced_ becomes T on its
  // diagonal and subdiagonal and the Householder vectors below them.
  Eigen::internal::tridiagonalization_inplace(reduced_, householder_);
  diagonal_ = reduced_.diagonal();
  subdiagonal_ = reduced_.diagonal<-1>();
  Eigen::HouseholderSequence<Eigen::MatrixXd, Eigen::VectorXd>(reduced_, householder_)
      .setLength(n - 1)
      .setShift(1)
      .evalTo(reflections_, scratch_);
  tridiagonal_.computeFromTridiagonal(diagonal_, subdiagonal_);
  eigenvalues_ = tridiagonal_.eigenvalues() * scale;
  eigenvectors_.resize(n, n);
  eigenvectors_.noalias() = reflections_ * tridiagonal_.eigenvectors();
}

}  // namespace animkit
