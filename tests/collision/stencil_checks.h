#pragma once
// Finite-difference checks of StencilDerivatives and random configurations, shared by the
// collision tests.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>

#include "animkit/collision/distance.h"

namespace animkit::test {

template <int V>
using Points = std::array<Vec3, V>;

/// Frobenius norm of a - b by a plain loop: Eigen's vectorized reduction of a fixed 12x12
/// difference trips a GCC 12 false positive (-Wuninitialized in its AVX-512 headers).
template <class A, class B>
double difference_norm(const A& a, const B& b) {
  double sum = 0.0;
  for (Eigen::Index j = 0; j < a.cols(); ++j) {
    for (Eigen::Index i = 0; i < a.rows(); ++i) sum += (a(i, j) - b(i, j)) * (a(i, j) - b(i, j));
  }
  return std::sqrt(sum);
}

/// Central differences (step h) of value(points) -> gradient, and of gradient(points) -> Hessian;
/// expects both within `tolerance` relative to the analytic derivatives' norms (plus a floor of
/// `tolerance` times the value's scale for vanishing derivatives).
template <int V, class Function>
void expect_derivatives_match(const Points<V>& points, Function&& function, double tolerance,
                              double h = 1e-6) {
  const StencilDerivatives<V> analytic = function(points);
  Eigen::Matrix<double, 3 * V, 1> gradient;
  Eigen::Matrix<double, 3 * V, 3 * V> hessian;
  for (int i = 0; i < 3 * V; ++i) {
    Points<V> plus = points, minus = points;
    plus[i / 3][i % 3] += h;
    minus[i / 3][i % 3] -= h;
    const StencilDerivatives<V> up = function(plus), down = function(minus);
    gradient[i] = (up.value - down.value) / (2 * h);
    hessian.col(i) = (up.gradient - down.gradient) / (2 * h);
  }
  const double gradient_scale = analytic.gradient.norm() + std::abs(analytic.value);
  const double hessian_scale =
      difference_norm(analytic.hessian, Eigen::Matrix<double, 3 * V, 3 * V>::Zero()) +
      gradient_scale;
  EXPECT_LE((analytic.gradient - gradient).norm(), tolerance * gradient_scale)
      << "gradient\n"
      << analytic.gradient.transpose() << "\nnumeric\n"
      << gradient.transpose();
  EXPECT_LE(difference_norm(analytic.hessian, hessian), tolerance * hessian_scale)
      << "hessian\n"
      << analytic.hessian << "\nnumeric\n"
      << hessian;
  EXPECT_LE(difference_norm(analytic.hessian, analytic.hessian.transpose()), 1e-12 * hessian_scale);
}

/// Uniform points in [-1, 1]^3.
class RandomPoints {
 public:
  explicit RandomPoints(unsigned seed) : rng_(seed) {}
  Vec3 point() { return Vec3(u_(rng_), u_(rng_), u_(rng_)); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * (0.5 * (u_(rng_) + 1.0)); }
  template <int V>
  Points<V> points() {
    Points<V> out;
    for (Vec3& p : out) p = point();
    return out;
  }
  std::mt19937& engine() { return rng_; }

 private:
  std::mt19937 rng_;
  std::uniform_real_distribution<double> u_{-1.0, 1.0};
};

/// sin^2 of the angle between u and v.
inline double sin2(const Vec3& u, const Vec3& v) {
  return u.cross(v).squaredNorm() / (u.squaredNorm() * v.squaredNorm());
}

}  // namespace animkit::test
