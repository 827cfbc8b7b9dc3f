// GCC 12's own AVX-512 intrinsics (_mm256_undefined_pd's self-initialization) trip
// -Wuninitialized when Eigen's fixed-size eigensolver is inlined with -march=native: a false
// positive in the compiler's headers (as -Wmaybe-uninitialized in CMakeLists.txt), silenced here
// for this file only.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "animkit/collision/psd_projection.h"

#include <Eigen/Eigenvalues>

namespace animkit {

namespace {

template <int N>
Eigen::Matrix<double, N, N> clamp_eigenvalues(const Eigen::Matrix<double, N, N>& matrix) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, N, N>> solver(matrix);
  const Eigen::Matrix<double, N, 1> clamped = solver.eigenvalues().cwiseMax(0.0);
  return solver.eigenvectors() * clamped.asDiagonal() * solver.eigenvectors().transpose();
}

}  // namespace

Eigen::Matrix<double, 5, 5> project_to_psd(const Eigen::Matrix<double, 5, 5>& matrix) {
  return clamp_eigenvalues<5>(matrix);
}
Eigen::Matrix<double, 6, 6> project_to_psd(const Eigen::Matrix<double, 6, 6>& matrix) {
  return clamp_eigenvalues<6>(matrix);
}
Eigen::Matrix<double, 9, 9> project_to_psd(const Eigen::Matrix<double, 9, 9>& matrix) {
  return clamp_eigenvalues<9>(matrix);
}
Eigen::Matrix<double, 12, 12> project_to_psd(const Eigen::Matrix<double, 12, 12>& matrix) {
  return clamp_eigenvalues<12>(matrix);
}

}  // namespace animkit
