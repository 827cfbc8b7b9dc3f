// One contact pair's barrier (src/cloth/contact/contact_pair.h): gradients and exact Hessians
// against central finite differences for every kind, on configurations inside the activation
// distance; the projected Hessian is PSD, the Gauss-Newton one rank one; beyond dhat everything
// is zero; contact is infinite.
// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's eigensolver is inlined with
// -march=native (a false positive in the compiler's own headers, see psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "../../src/cloth/contact/contact_pair.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace animkit {
namespace {

constexpr double kDhat = 0.1;  // activation distance (m); the barrier takes its square

LogBarrier barrier() {
  return *LogBarrier::create(kDhat * kDhat);
}

// Four positions for the pair's slots: a triangle or an edge near the origin, the other
// primitive at distance 0.02..0.08 above it, randomly perturbed.
std::array<Vec3, 4> configuration(ContactKind kind, std::mt19937& rng) {
  std::uniform_real_distribution<double> jitter(-0.2, 0.2), height(0.02, 0.08);
  const double up = height(rng);
  switch (kind) {
    case ContactKind::point_triangle:
      return {Vec3(0.2 + 0.1 * jitter(rng), up, 0.2 + 0.1 * jitter(rng)),
              Vec3(0, 0.01 * jitter(rng), 0), Vec3(1, 0.01 * jitter(rng), 0.1 * jitter(rng)),
              Vec3(0.1 * jitter(rng), 0.01 * jitter(rng), 1)};
    case ContactKind::edge_edge:
      return {Vec3(-0.5, 0.01 * jitter(rng), jitter(rng)),
              Vec3(0.5, 0.01 * jitter(rng), jitter(rng)), Vec3(jitter(rng), up, -0.5),
              Vec3(jitter(rng), up, 0.5)};
    case ContactKind::ground:
      return {Vec3(jitter(rng), up, jitter(rng)), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  }
  return {};
}

ContactPair pair_of(ContactKind kind) {
  ContactPair pair;
  pair.kind = kind;
  pair.vertices = {0, 1, 2, 3};
  pair.mollifier_threshold = 1e-3;  // 1e-3 |e_a|^2 |e_b|^2 for unit-length edges
  return pair;
}

class ContactPairKinds : public testing::TestWithParam<ContactKind> {};

TEST_P(ContactPairKinds, DerivativesMatchFiniteDifferences) {
  std::mt19937 rng(7);
  const ContactPair pair = pair_of(GetParam());
  const LogBarrier b = barrier();
  const int dofs = 3 * pair.vertex_count();
  for (int trial = 0; trial < 20; ++trial) {
    std::array<Vec3, 4> p = configuration(pair.kind, rng);
    const StencilDerivatives<4> exact = contact_barrier_derivatives(pair, p, 0.0, b, false);
    ASSERT_GT(exact.value, 0.0);
    EXPECT_NEAR(exact.value, contact_barrier(pair, p, 0.0, b), 1e-12 * exact.value);
    const double eps = 1e-7;
    for (int k = 0; k < dofs; ++k) {
      std::array<Vec3, 4> plus = p, minus = p;
      plus[k / 3][k % 3] += eps;
      minus[k / 3][k % 3] -= eps;
      const double fd =
          (contact_barrier(pair, plus, 0.0, b) - contact_barrier(pair, minus, 0.0, b)) / (2 * eps);
      EXPECT_NEAR(exact.gradient[k], fd, 1e-5 * (std::abs(fd) + 1e-6)) << "dof " << k;
      const auto g_plus = contact_barrier_derivatives(pair, plus, 0.0, b, false).gradient;
      const auto g_minus = contact_barrier_derivatives(pair, minus, 0.0, b, false).gradient;
      const Eigen::Matrix<double, 12, 1> column = (g_plus - g_minus) / (2 * eps);
      EXPECT_LT((exact.hessian.col(k) - column).norm(), 1e-4 * (column.norm() + 1e-6))
          << "Hessian column " << k;
    }
    // The projected Hessian is PSD and the nearest such: equal to the exact one when that is.
    const auto projected = contact_barrier_derivatives(pair, p, 0.0, b).hessian;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> eig(projected);
    EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-9 * projected.norm());
  }
}

// The Gauss-Newton Hessian keeps the barrier's curvature along the distance and drops the
// distance's own curvature: PSD and rank one, and exact for a move that changes the distance
// linearly (the upper primitive translated along the pair's normal: its configurations are
// point over the triangle's face, or crossing edges, whose mollifier is 1).
TEST_P(ContactPairKinds, GaussNewtonHessianIsRankOneAndExactAlongTheNormal) {
  std::mt19937 rng(11);
  const ContactPair pair = pair_of(GetParam());
  const LogBarrier b = barrier();
  const std::vector<int> upper =
      pair.kind == ContactKind::edge_edge ? std::vector<int>{2, 3} : std::vector<int>{0};
  for (int trial = 0; trial < 20; ++trial) {
    const std::array<Vec3, 4> p = configuration(pair.kind, rng);
    const StencilDerivatives<4> exact = contact_barrier_derivatives(pair, p, 0.0, b, false);
    const Eigen::Matrix<double, 12, 12> gn = contact_barrier_gauss_newton_hessian(pair, p, 0.0, b);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 12, 12>> eig(gn);
    const double largest = eig.eigenvalues().maxCoeff();
    ASSERT_GT(largest, 0.0);
    EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-12 * largest);
    EXPECT_LT(eig.eigenvalues()(10), 1e-12 * largest);  // rank one
    // The gradient of the barrier at the upper primitive's first vertex points along -n.
    const Vec3 normal = exact.gradient.segment<3>(3 * upper.front()).normalized();
    Eigen::Matrix<double, 12, 1> move = Eigen::Matrix<double, 12, 1>::Zero();
    for (const int v : upper) move.segment<3>(3 * v) = normal;
    const double along_exact = move.dot(exact.hessian * move);
    EXPECT_NEAR(move.dot(gn * move), along_exact, 1e-9 * std::abs(along_exact));
  }
}

TEST_P(ContactPairKinds, NothingBeyondTheActivationDistance) {
  std::mt19937 rng(3);
  const ContactPair pair = pair_of(GetParam());
  std::array<Vec3, 4> far = configuration(pair.kind, rng);
  // Lift the upper primitive (the point, or the second edge) 1 m: far beyond dhat = 0.1 m.
  for (int i : pair.kind == ContactKind::edge_edge ? std::vector<int>{2, 3} : std::vector<int>{0})
    far[i].y() += 1.0;
  EXPECT_EQ(contact_barrier(pair, far, 0.0, barrier()), 0.0);
  const auto d = contact_barrier_derivatives(pair, far, 0.0, barrier());
  EXPECT_EQ(d.gradient.norm(), 0.0);
  EXPECT_EQ(d.hessian.norm(), 0.0);
  EXPECT_EQ(contact_barrier_gauss_newton_hessian(pair, far, 0.0, barrier()).norm(), 0.0);
}

// The box test the loops over candidate pairs run first: it passes over only pairs whose
// distance is at least dhat's root, and it does pass over most far pairs.
TEST_P(ContactPairKinds, TheBoxTestSkipsOnlyPairsBeyondTheActivationDistance) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> shift(-0.4, 0.4);
  const ContactPair pair = pair_of(GetParam());
  const LogBarrier b = barrier();
  int skipped = 0, far = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    std::array<Vec3, 4> p = configuration(pair.kind, rng);
    // Move the upper primitive anywhere within 0.4 m: near, touching the boxes, or far away.
    const Vec3 offset(shift(rng), shift(rng), shift(rng));
    for (int i : pair.kind == ContactKind::edge_edge ? std::vector<int>{2, 3} : std::vector<int>{0})
      p[i] += offset;
    const double d = contact_distance_squared(pair, p, -1.0);
    far += d >= b.dhat();
    if (!contact_beyond(pair, p, b.dhat())) continue;
    ++skipped;
    EXPECT_GE(d, b.dhat()) << "trial " << trial;
    EXPECT_EQ(contact_barrier(pair, p, -1.0, b), 0.0);
  }
  if (pair.kind == ContactKind::ground) {
    EXPECT_EQ(skipped, 0);  // a plane has no box: never skipped
  } else {
    EXPECT_GT(skipped, far / 4) << "of " << far << " far pairs";
  }
}

TEST(ContactPair, AParticleOnOrBelowTheGroundIsInContact) {
  const ContactPair pair = pair_of(ContactKind::ground);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(contact_barrier(pair, {Vec3(0, 1.0, 0)}, 1.0, barrier()), inf);
  EXPECT_EQ(contact_barrier(pair, {Vec3(0, 0.5, 0)}, 1.0, barrier()), inf);
  EXPECT_GT(contact_barrier(pair, {Vec3(0, 1.05, 0)}, 1.0, barrier()), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Kinds, ContactPairKinds,
                         testing::Values(ContactKind::point_triangle, ContactKind::edge_edge,
                                         ContactKind::ground),
                         [](const auto& param_info) {
                           switch (param_info.param) {
                             case ContactKind::point_triangle:
                               return std::string("PointTriangle");
                             case ContactKind::edge_edge:
                               return std::string("EdgeEdge");
                             case ContactKind::ground:
                               return std::string("Ground");
                           }
                           return std::string("Unknown");
                         });

}  // namespace
}  // namespace animkit
