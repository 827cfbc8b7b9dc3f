// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's dense products are inlined
// with -march=native at -O1 (a false positive in the compiler's own headers, see
// psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "animkit/kinematics/euler_angles.h"

#include <gtest/gtest.h>

#include <random>

#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kPi;
const EulerOrder kOrders[] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

// The rotation matrix built independently: a product of the three axis matrices written out.
Eigen::Matrix3d axis_matrix(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d m;
  if (axis == 0) m << 1, 0, 0, 0, c, -s, 0, s, c;
  if (axis == 1) m << c, 0, s, 0, 1, 0, -s, 0, c;
  if (axis == 2) m << c, -s, 0, s, c, 0, 0, 0, 1;
  return m;
}

TEST(EulerAngles, ComposeInTheGivenOrder) {
  for (const EulerOrder& order : kOrders) {
    const Vec3 angles(0.3, -1.1, 2.5);
    const Eigen::Matrix3d expected = axis_matrix(order[0], angles[0]) *
                                     axis_matrix(order[1], angles[1]) *
                                     axis_matrix(order[2], angles[2]);
    EXPECT_LT((euler_to_quat(order, angles).toRotationMatrix() - expected).norm(), 1e-14);
  }
}

TEST(EulerAngles, DecomposeReturnsTheSameAnglesInTheirRanges) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> outer(-kPi + 1e-6, kPi - 1e-6);
  std::uniform_real_distribution<double> middle(-kPi / 2 + 1e-3, kPi / 2 - 1e-3);
  for (const EulerOrder& order : kOrders) {
    for (int trial = 0; trial < 200; ++trial) {
      const Vec3 angles(outer(rng), middle(rng), outer(rng));
      const Vec3 back = quat_to_euler(order, euler_to_quat(order, angles));
      EXPECT_LT((back - angles).norm(), 1e-9) << back.transpose() << " vs " << angles.transpose();
    }
  }
}

TEST(EulerAngles, GimbalLockGivesTheSameRotationWithoutNaN) {
  for (const EulerOrder& order : kOrders) {
    for (const double b : {kPi / 2, -kPi / 2}) {
      for (const double a : {0.0, 0.7, -2.9}) {
        for (const double c : {0.0, 0.4, 3.0}) {
          const Quat q = euler_to_quat(order, Vec3(a, b, c));
          const Vec3 back = quat_to_euler(order, q);
          ASSERT_TRUE(back.allFinite());
          EXPECT_NEAR(std::abs(back[1]), kPi / 2, 1e-7);
          EXPECT_EQ(back[2], 0.0);
          EXPECT_LT(euler_to_quat(order, back).angularDistance(q), 1e-9);
        }
      }
    }
  }
}

TEST(EulerAngles, RandomRotationsComeBackForEveryOrder) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (const EulerOrder& order : kOrders) {
    for (int trial = 0; trial < 200; ++trial) {
      const Quat q = Quat(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
      EXPECT_LT(euler_to_quat(order, quat_to_euler(order, q)).angularDistance(q), 1e-12);
    }
  }
}

}  // namespace
}  // namespace animkit
