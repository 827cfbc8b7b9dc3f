#include "animkit/cloth/spring_energy.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <random>

namespace animkit {
namespace {

// Central differences of the energy (gradient) and of the gradient (Hessian block).
Vec3 numeric_gradient(const Vec3& a, const Vec3& b, double k, double rest) {
  constexpr double h = 1e-6;
  Vec3 g;
  for (int c = 0; c < 3; ++c) {
    Vec3 plus = a, minus = a;
    plus[c] += h;
    minus[c] -= h;
    g[c] = (spring_energy(plus, b, k, rest) - spring_energy(minus, b, k, rest)) / (2 * h);
  }
  return g;
}

Mat3 numeric_hessian(const Vec3& a, const Vec3& b, double k, double rest) {
  constexpr double h = 1e-6;
  Mat3 m;
  for (int c = 0; c < 3; ++c) {
    Vec3 plus = a, minus = a;
    plus[c] += h;
    minus[c] -= h;
    m.col(c) = (spring_gradient(plus, b, k, rest) - spring_gradient(minus, b, k, rest)) / (2 * h);
  }
  return m;
}

class SpringEnergy : public testing::Test {
 protected:
  std::mt19937 rng{11};
  std::uniform_real_distribution<double> u{-1.0, 1.0};
  Vec3 random_vec() { return Vec3(u(rng), u(rng), u(rng)); }
};

TEST_F(SpringEnergy, GradientMatchesFiniteDifferences) {
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = random_vec(), b = random_vec();
    const double k = 10.0 + 100.0 * std::abs(u(rng));
    const double rest = 0.1 + std::abs(u(rng));  // both stretched and compressed springs
    const Vec3 analytic = spring_gradient(a, b, k, rest);
    EXPECT_LT((analytic - numeric_gradient(a, b, k, rest)).norm(), 1e-6 * (1.0 + analytic.norm()));
    // dE/dx_b = -dE/dx_a: swapping the ends flips the gradient.
    EXPECT_LT((spring_gradient(b, a, k, rest) + analytic).norm(), 1e-12 * (1.0 + analytic.norm()));
  }
}

TEST_F(SpringEnergy, ExactHessianMatchesFiniteDifferences) {
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = random_vec(), b = random_vec();
    const double k = 10.0 + 100.0 * std::abs(u(rng));
    const double rest = 0.1 + std::abs(u(rng));
    const Mat3 exact = spring_hessian_block(a, b, k, rest, /*projected=*/false);
    EXPECT_LT((exact - numeric_hessian(a, b, k, rest)).norm(), 1e-5 * (1.0 + exact.norm()));
    EXPECT_LT((exact - exact.transpose()).norm(), 1e-12 * exact.norm());
  }
}

TEST_F(SpringEnergy, ProjectedHessianIsPsdAndExactWhenStretched) {
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = random_vec(), b = random_vec();
    const double length = (a - b).norm();
    const double k = 100.0;
    for (double rest : {0.5 * length, 2.0 * length}) {  // stretched, then compressed
      const Mat3 projected = spring_hessian_block(a, b, k, rest, true);
      const Eigen::Vector3d eigenvalues =
          Eigen::SelfAdjointEigenSolver<Mat3>(projected).eigenvalues();
      EXPECT_GE(eigenvalues.minCoeff(), -1e-12 * k);
      const Mat3 exact = spring_hessian_block(a, b, k, rest, false);
      if (rest < length) {
        EXPECT_LT((projected - exact).norm(), 1e-12 * k);
      } else {
        // Compressed: the exact block has a negative transverse eigenvalue k (1 - L/l) < 0.
        EXPECT_LT(Eigen::SelfAdjointEigenSolver<Mat3>(exact).eigenvalues().minCoeff(), 0.0);
      }
    }
  }
}

TEST_F(SpringEnergy, RestSpringHasNoEnergyOrForce) {
  const Vec3 a(0, 0, 0), b(0.3, 0.4, 0.0);
  EXPECT_EQ(spring_energy(a, b, 100.0, 0.5), 0.0);
  EXPECT_LT(spring_gradient(a, b, 100.0, 0.5).norm(), 1e-14);
  EXPECT_EQ(spring_gradient(a, a, 100.0, 0.5), Vec3::Zero());  // coincident: no direction
}

}  // namespace
}  // namespace animkit
