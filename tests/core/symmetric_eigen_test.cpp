// GCC 12's AVX-512 -Wuninitialized false positive in Eigen's eigensolver at -O1 (the sanitizer
// build); see src/core/symmetric_eigen.cpp.
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "animkit/core/symmetric_eigen.h"

#include <gtest/gtest.h>

#include <random>

namespace animkit {
namespace {

// A random symmetric matrix with some repeated and zero eigenvalues when `degenerate`.
Eigen::MatrixXd random_symmetric(Eigen::Index n, std::mt19937_64& rng, bool degenerate) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd m(n, n);
  for (Eigen::Index i = 0; i < m.size(); ++i) m.data()[i] = normal(rng);
  if (!degenerate) return m + m.transpose();
  // Rank-deficient, like J J^T with fewer joints than effector rows: B B^T with B n x n/2.
  const Eigen::MatrixXd b = m.leftCols(n / 2);
  return b * b.transpose();
}

TEST(SymmetricEigen, MatchesEigensSolverAndDecomposesTheMatrix) {
  std::mt19937_64 rng(5);
  SymmetricEigen eigen;
  for (const int n : {1, 2, 3, 6, 12, 24, 13}) {
    for (const bool degenerate : {false, true}) {
      const Eigen::MatrixXd a = random_symmetric(n, rng, degenerate);
      eigen.compute(a);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> reference(a);
      const double tolerance = 1e-12 * std::max(1.0, a.cwiseAbs().maxCoeff()) * n;
      EXPECT_LE((eigen.eigenvalues() - reference.eigenvalues()).cwiseAbs().maxCoeff(), tolerance)
          << n;
      const Eigen::MatrixXd& u = eigen.eigenvectors();
      EXPECT_LE((u.transpose() * u - Eigen::MatrixXd::Identity(n, n)).cwiseAbs().maxCoeff(),
                1e-12 * n)
          << n;
      EXPECT_LE((u * eigen.eigenvalues().asDiagonal() * u.transpose() - a).cwiseAbs().maxCoeff(),
                tolerance)
          << n;
      for (Eigen::Index i = 1; i < n; ++i) {
        EXPECT_LE(eigen.eigenvalues()[i - 1], eigen.eigenvalues()[i]);
      }
    }
  }
}

TEST(SymmetricEigen, ReadsOnlyTheLowerTriangle) {
  std::mt19937_64 rng(6);
  const Eigen::MatrixXd a = random_symmetric(8, rng, false);
  Eigen::MatrixXd lower_only = a;
  lower_only.triangularView<Eigen::StrictlyUpper>().setConstant(1e6);
  SymmetricEigen from_full, from_lower;
  from_full.compute(a);
  from_lower.compute(lower_only);
  EXPECT_EQ(from_full.eigenvalues(), from_lower.eigenvalues());
  EXPECT_EQ(from_full.eigenvectors(), from_lower.eigenvectors());
}

}  // namespace
}  // namespace animkit
