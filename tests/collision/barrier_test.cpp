// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's 12x12 products are inlined with
// -march=native (a false positive in the compiler's own headers, see psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"

#include "animkit/collision/barrier.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <random>

#include "animkit/collision/psd_projection.h"

namespace animkit {
namespace {

TEST(Barrier, DerivativesMatchFiniteDifferences) {
  for (double dhat : {1e-6, 1e-2, 1.0}) {
    const LogBarrier barrier = LogBarrier::create(dhat).value();
    for (double ratio = 1e-4; ratio < 0.999; ratio *= 1.5) {
      const double d = ratio * dhat, h = 1e-7 * d;
      const double first = barrier.first_derivative(d), second = barrier.second_derivative(d);
      const double numeric_first = (barrier.value(d + h) - barrier.value(d - h)) / (2 * h);
      const double numeric_second =
          (barrier.first_derivative(d + h) - barrier.first_derivative(d - h)) / (2 * h);
      // b' ~ dhat^2 / d and b'' ~ dhat^2 / d^2 near 0: relative bounds.
      EXPECT_NEAR(first, numeric_first, 1e-6 * std::abs(first) + 1e-9 * dhat) << d;
      EXPECT_NEAR(second, numeric_second, 1e-6 * std::abs(second) + 1e-9) << d;
      EXPECT_GT(barrier.value(d), 0.0);
      EXPECT_LT(first, 0.0);   // pushes apart
      EXPECT_GT(second, 0.0);  // convex in d
    }
  }
}

TEST(Barrier, HandComputedValueAndSmoothCutoff) {
  const LogBarrier barrier = LogBarrier::create(4.0).value();
  EXPECT_DOUBLE_EQ(barrier.value(1.0), 9.0 * std::log(4.0));  // -(1 - 4)^2 ln(1/4)
  // C^2 at dhat: value and both derivatives tend to 0 from below and are 0 beyond.
  const double below = 4.0 * (1.0 - 1e-6);
  EXPECT_LT(barrier.value(below), 1e-15);
  EXPECT_LT(std::abs(barrier.first_derivative(below)), 1e-10);
  EXPECT_LT(std::abs(barrier.second_derivative(below)), 1e-5);
  for (double d : {4.0, 5.0, 1e9}) {
    EXPECT_EQ(barrier.value(d), 0.0);
    EXPECT_EQ(barrier.first_derivative(d), 0.0);
    EXPECT_EQ(barrier.second_derivative(d), 0.0);
  }
  EXPECT_GT(barrier.value(1e-12), 400.0);  // 16 ln(4e12): unbounded at contact
}

TEST(Barrier, RejectsNonPositiveOrNonFiniteDhat) {
  EXPECT_EQ(LogBarrier::create(0.0).error().message,
            "barrier dhat must be a positive finite squared distance, got 0");
  EXPECT_EQ(LogBarrier::create(-1e-3).error().message,
            "barrier dhat must be a positive finite squared distance, got -0.001");
  EXPECT_EQ(LogBarrier::create(std::numeric_limits<double>::quiet_NaN()).error().message,
            "barrier dhat must be a positive finite squared distance, got nan");
  EXPECT_FALSE(LogBarrier::create(std::numeric_limits<double>::infinity()).has_value());
  EXPECT_EQ(LogBarrier::create(1e-6).value().dhat(), 1e-6);
}

Eigen::VectorXd eigenvalues(const Eigen::MatrixXd& m) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(m).eigenvalues();
}

Eigen::MatrixXd projected(const Eigen::MatrixXd& m) {
  return project_to_psd(Eigen::Matrix<double, 12, 12>(m));
}

TEST(PsdProjection, ClampsNegativeEigenvaluesOnly) {
  std::mt19937 rng(31);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 50; ++trial) {
    Eigen::MatrixXd a(12, 12);
    for (int i = 0; i < 12; ++i) {
      for (int j = 0; j < 12; ++j) a(i, j) = normal(rng);
    }
    const Eigen::MatrixXd symmetric = a + a.transpose();
    const Eigen::MatrixXd projection = projected(symmetric);
    const double scale = symmetric.norm();
    EXPECT_GE(eigenvalues(projection).minCoeff(), -1e-12 * scale);
    // Frobenius distance to the projection = norm of the clamped (negative) eigenvalues.
    const double clamped = eigenvalues(symmetric).cwiseMin(0.0).norm();
    EXPECT_NEAR((projection - symmetric).norm(), clamped, 1e-10 * scale);
    EXPECT_GT(clamped, 0.0);  // random symmetric matrices are indefinite
    // Positive eigenvalues kept: the projection of a PSD matrix is itself.
    const Eigen::MatrixXd psd = a * a.transpose();
    EXPECT_LT((projected(psd) - psd).norm(), 1e-12 * psd.norm());
    EXPECT_LT((projection - projection.transpose()).norm(), 1e-12 * scale);
  }
  const Eigen::Matrix<double, 6, 6> zero = Eigen::Matrix<double, 6, 6>::Zero();
  EXPECT_EQ(project_to_psd(zero), zero);
  Eigen::Matrix<double, 9, 9> diagonal = Eigen::Matrix<double, 9, 9>::Identity();
  diagonal(4, 4) = -3.0;
  Eigen::Matrix<double, 9, 9> expected = diagonal;
  expected(4, 4) = 0.0;
  EXPECT_LT((project_to_psd(diagonal) - expected).norm(), 1e-14);
}

}  // namespace
}  // namespace animkit
