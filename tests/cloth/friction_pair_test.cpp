// One contact pair's lagged friction (src/cloth/contact/friction_pair.h): the closest points'
// weights against the classified distance kernels (separate code); the normal force is the
// barrier's force along the distance (finite differences); f0 is IPC's C^1 smoothing (C^2 here)
// and convex; the tangential motion is relative to the obstacle's own.
// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's eigensolver is inlined with
// -march=native (a false positive in the compiler's own headers, see psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "../../src/cloth/contact/friction_pair.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <random>

namespace animkit {
namespace {

constexpr double kFrictionDhat = 0.1;  // activation distance (m); the barrier takes its square

// A ground pair's positions: the particle, then unused vertices.
std::array<Vec3, 4> particle_at(const Vec3& p) {
  return {p, Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
}

Vec3 random_contact_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return Vec3(u(rng), u(rng), u(rng));
}

TEST(FrictionPair, ClosestPointWeightsSpanTheClassifiedDistance) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 2000; ++trial) {
    std::array<Vec3, 4> p;
    for (Vec3& v : p) v = random_contact_point(rng);
    for (const ContactKind kind : {ContactKind::point_triangle, ContactKind::edge_edge}) {
      const ContactPair pair{kind, {0, 1, 2, 3}};
      const std::array<double, 4> w = closest_point_weights(pair, p);
      Vec3 separation = Vec3::Zero();
      for (int i = 0; i < 4; ++i) separation += w[i] * p[i];
      const double d = contact_distance_squared(pair, p, 0.0);
      EXPECT_NEAR(separation.squaredNorm(), d, 1e-12 * (1.0 + d)) << trial;
      // Weights of a point on each primitive: the first's sum to 1, the second's to -1.
      EXPECT_NEAR(w[0] + (kind == ContactKind::edge_edge ? w[1] : 0.0), 1.0, 1e-14);
      EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 0.0, 1e-14);
    }
  }
}

TEST(FrictionPair, NormalForceIsTheBarriersForceAlongTheDistance) {
  const LogBarrier barrier = *LogBarrier::create(kFrictionDhat * kFrictionDhat);
  const double kappa = 7.0, mu = 0.4, gap = 0.03;
  const ContactPair ground{ContactKind::ground, {0, -1, -1, -1}};
  const auto energy = [&](double y) { return kappa * barrier.value((y - 0.0) * (y - 0.0)); };
  const auto lagged =
      lag_friction_pair(ground, particle_at(Vec3(0.2, gap, 0.1)), 0.0, kappa, barrier, mu);
  ASSERT_TRUE(lagged);
  const double h = 1e-7, force = -(energy(gap + h) - energy(gap - h)) / (2 * h);
  EXPECT_NEAR(lagged->normal_force, force, 1e-6 * force);
  EXPECT_DOUBLE_EQ(lagged->mu_lambda, mu * lagged->normal_force);
  // The ground's tangent plane is horizontal.
  EXPECT_NEAR((lagged->basis.transpose() * Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_TRUE((lagged->basis.transpose() * lagged->basis).isIdentity(1e-15));
  // Beyond dhat, at contact, or with mu = 0: nothing to lag.
  EXPECT_FALSE(lag_friction_pair(ground, particle_at(Vec3(0, 0.2, 0)), 0.0, kappa, barrier, mu));
  EXPECT_FALSE(lag_friction_pair(ground, particle_at(Vec3(0, 0.0, 0)), 0.0, kappa, barrier, mu));
  EXPECT_FALSE(lag_friction_pair(ground, particle_at(Vec3(0, gap, 0)), 0.0, kappa, barrier, 0.0));
}

TEST(FrictionPair, SmoothingIsC2AtEpsAndConvex) {
  const double eps = 1e-3, h = 1e-9;
  EXPECT_DOUBLE_EQ(friction_f0(eps, eps), eps);
  EXPECT_NEAR(friction_f0(eps * (1 - 1e-12), eps), eps, 1e-14);
  EXPECT_NEAR(friction_f1(eps * (1 - 1e-12), eps), 1.0, 1e-10);
  EXPECT_NEAR(friction_f1(0.0, eps), 0.0, 0.0);
  for (const double y : {1e-5, 3e-4, 9e-4, 2e-3}) {
    const double fd = (friction_f0(y + h, eps) - friction_f0(y - h, eps)) / (2 * h);
    EXPECT_NEAR(friction_f1(y, eps), fd, 1e-6) << y;
    EXPECT_NEAR(friction_f1_over_y(y, eps) * y, friction_f1(y, eps), 1e-12) << y;
  }
  // f1' just below eps tends to 0 (C^2), and f1 only rises.
  const double below = eps * (1 - 1e-6);
  EXPECT_NEAR((friction_f1(below, eps) - friction_f1(below - 1e-9, eps)) / 1e-9, 0.0, 1e-2);
  for (double y = 0.0; y < 2 * eps; y += eps / 64)
    EXPECT_LE(friction_f1(y, eps), friction_f1(y + eps / 64, eps));
}

TEST(FrictionPair, TangentHessianIsPsdAndMatchesTheGradient) {
  const double eps = 1e-3, h = 1e-10;
  for (const Eigen::Vector2d& u :
       {Eigen::Vector2d(2e-4, -1e-4), Eigen::Vector2d(3e-3, 1e-3), Eigen::Vector2d(0.0, 0.0)}) {
    const Eigen::Matrix2d hessian = friction_tangent_hessian(u, eps);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(hessian);
    EXPECT_GE(eigen.eigenvalues().minCoeff(), -1e-9 * eigen.eigenvalues().maxCoeff());
    if (u.norm() == 0.0) continue;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d plus = u, minus = u;
      plus[k] += h;
      minus[k] -= h;
      const Eigen::Vector2d fd = (friction_f1_over_y(plus.norm(), eps) * plus -
                                  friction_f1_over_y(minus.norm(), eps) * minus) /
                                 (2 * h);
      EXPECT_LE((hessian.col(k) - fd).norm(), 1e-5 * hessian.norm()) << u.transpose();
    }
  }
}

TEST(FrictionPair, SlidingIsMeasuredAgainstTheObstaclesOwnMotion) {
  // A cloth particle (vertex 0) above an obstacle triangle (vertices 1..3 of the index space).
  const LogBarrier barrier = *LogBarrier::create(kFrictionDhat * kFrictionDhat);
  const ContactPair pair{ContactKind::point_triangle, {0, 1, 2, 3}};
  const std::array<Vec3, 4> p{Vec3(0.2, 0.05, 0.2), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)};
  auto lagged = lag_friction_pair(pair, p, 0.0, 1.0, barrier, 0.5);
  ASSERT_TRUE(lagged);
  const Eigen::VectorXd start = p[0];
  const Vec3 obstacle_move(0.01, 0.0, -0.02);
  Vec3 own = Vec3::Zero();
  for (int i = 1; i < 4; ++i) own += lagged->weights[i] * obstacle_move;
  lagged->obstacle_motion = own;
  // Moving with the triangle: no sliding. Standing still: sliding by the triangle's motion.
  const Eigen::VectorXd riding = start + obstacle_move;
  EXPECT_NEAR(friction_tangent_motion(*lagged, riding, start, 1).norm(), 0.0, 1e-15);
  EXPECT_NEAR(friction_tangent_motion(*lagged, start, start, 1).norm(), obstacle_move.norm(),
              1e-15);
  // A normal motion is not sliding.
  const Eigen::VectorXd lifted = riding + Vec3(0.0, 0.01, 0.0);
  EXPECT_NEAR(friction_tangent_motion(*lagged, lifted, start, 1).norm(), 0.0, 1e-15);
}

}  // namespace
}  // namespace animkit
