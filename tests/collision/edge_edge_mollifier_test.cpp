#include "animkit/collision/edge_edge_mollifier.h"

#include <gtest/gtest.h>

#include "stencil_checks.h"

namespace animkit {
namespace {

using test::Points;
using test::RandomPoints;

// Nearly parallel edges: b's direction is a's turned by a small random amount.
Points<4> nearly_parallel(RandomPoints& random, double tilt) {
  Points<4> x = random.points<4>();
  x[3] = x[2] + 1.3 * (x[1] - x[0]) + tilt * random.point();
  return x;
}

TEST(EdgeEdgeMollifier, DerivativesMatchFiniteDifferencesBelowTheThreshold) {
  RandomPoints random(21);
  int below = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Points<4> x = nearly_parallel(random, 0.05);
    const double c = (x[1] - x[0]).cross(x[3] - x[2]).squaredNorm();
    if (c < 1e-8) continue;
    const double eps_x = c * random.uniform(1.2, 5.0);  // c / eps_x in (0.2, 0.83): m < 1
    const auto derivatives = [eps_x](const Points<4>& y) {
      return edge_edge_mollifier_derivatives(y[0], y[1], y[2], y[3], eps_x);
    };
    EXPECT_LT(derivatives(x).value, 1.0);
    EXPECT_NEAR(derivatives(x).value, edge_edge_mollifier(x[0], x[1], x[2], x[3], eps_x), 1e-12);
    test::expect_derivatives_match<4>(x, derivatives, 1e-5, 1e-7);
    ++below;
  }
  EXPECT_GT(below, 150);
}

TEST(EdgeEdgeMollifier, TheGradientAloneIsTheFullDerivativesGradient) {
  RandomPoints random(22);
  for (int trial = 0; trial < 200; ++trial) {
    const Points<4> x = nearly_parallel(random, trial % 2 == 0 ? 0.05 : 1.0);
    const double c = (x[1] - x[0]).cross(x[3] - x[2]).squaredNorm();
    const double eps_x = (c + 1e-12) * random.uniform(0.5, 5.0);  // m < 1 and m = 1 both
    const auto full = edge_edge_mollifier_derivatives(x[0], x[1], x[2], x[3], eps_x);
    const auto alone = edge_edge_mollifier_gradient(x[0], x[1], x[2], x[3], eps_x);
    EXPECT_NEAR(alone.value, full.value, 1e-14);
    EXPECT_LE((alone.gradient - full.gradient).norm(), 1e-14 * (1.0 + full.gradient.norm()));
  }
}

TEST(EdgeEdgeMollifier, IsOneAboveTheThresholdAndVanishesForParallelEdges) {
  const Vec3 a0(0, 0, 0), a1(1, 0, 0), b0(0, 1, 0);
  const double eps_x = edge_edge_mollifier_threshold(a0, a1, b0, Vec3(0, 1, 1));
  EXPECT_DOUBLE_EQ(eps_x, 1e-3);
  const auto crossing = edge_edge_mollifier_derivatives(a0, a1, b0, Vec3(0, 1, 1), eps_x);
  EXPECT_EQ(crossing.value, 1.0);
  EXPECT_EQ(crossing.gradient.norm(), 0.0);
  EXPECT_EQ(test::difference_norm(crossing.hessian, Eigen::Matrix<double, 12, 12>::Zero()), 0.0);
  EXPECT_EQ(edge_edge_mollifier(a0, a1, b0, Vec3(2, 1, 0), eps_x), 0.0);  // parallel
  // C^1 at c = eps_x: value 1 and slope 0 on both sides. c = |(1,0,0) x (1,0,z)|^2 = z^2.
  const double z = std::sqrt(eps_x);
  for (double factor : {1.0 - 1e-6, 1.0 + 1e-6}) {
    const auto near = edge_edge_mollifier_derivatives(a0, a1, b0, Vec3(1, 1, factor * z), eps_x);
    EXPECT_NEAR(near.value, 1.0, 1e-11);
    EXPECT_LT(near.gradient.norm(), 1e-3);
  }
}

}  // namespace
}  // namespace animkit
