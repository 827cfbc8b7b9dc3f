#pragma once
// Seeded random rotations, axes and joint limits shared by the joint limit tests.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "animkit/kinematics/joint_limits.h"

namespace animkit::limit_samples {

constexpr double kPi = std::numbers::pi;

inline Quat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  Quat q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized();
}

inline Vec3 random_axis(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

inline double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

inline Quat about(double angle, const Vec3& axis) {
  return Quat(Eigen::AngleAxisd(angle, axis));
}

inline HingeLimit random_hinge(std::mt19937_64& rng) {
  double a = uniform(rng, -kPi, kPi), b = uniform(rng, -kPi, kPi);
  return HingeLimit{random_axis(rng), std::min(a, b), std::max(a, b)};
}

inline BallLimit random_ball(std::mt19937_64& rng) {
  double a = uniform(rng, -kPi, kPi), b = uniform(rng, -kPi, kPi);
  return BallLimit{random_axis(rng), uniform(rng, 0.0, kPi), std::min(a, b), std::max(a, b)};
}

inline bool same_bits(const Quat& a, const Quat& b) {
  return a.coeffs() == b.coeffs();
}

// Same rotation: q or -q, coefficient by coefficient.
inline double rotation_gap(const Quat& a, const Quat& b) {
  return std::min((a.coeffs() - b.coeffs()).norm(), (a.coeffs() + b.coeffs()).norm());
}

}  // namespace animkit::limit_samples
