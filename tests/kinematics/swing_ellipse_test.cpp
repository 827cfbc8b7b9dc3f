// Elliptical swing cones: the nearest point of the ellipse (swing_ellipse.cpp) seen through
// BallLimit: equal half-angles give the circular cone, results are inside and idempotent,
// inside rotations are kept bit for bit, and the swing's rotation vector goes to the nearest
// point of the ellipse, on thousands of seeded random rotations.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "animkit/core/quaternion_math.h"
#include "animkit/kinematics/joint_limits.h"
#include "limit_samples.h"

namespace animkit {
namespace {

using namespace limit_samples;

BallLimit random_elliptical_ball(std::mt19937_64& rng) {
  BallLimit ball = random_ball(rng);
  ball.swing_axis = ball.twist_axis.cross(random_axis(rng)).normalized();
  ball.swing_angle_2 = uniform(rng, 0.0, kPi);
  const int degenerate = std::uniform_int_distribution<int>(0, 9)(rng);
  if (degenerate == 0) ball.swing_angle = 0.0;  // a flat cone: swings about one axis only
  if (degenerate == 1) ball.swing_angle_2 = 0.0;
  return ball;
}

// The swing's rotation vector in the elliptical cone's plane coordinates.
Eigen::Vector2d swing_vector(const BallLimit& ball, const Quat& q) {
  const Quat swing = swing_twist(q, ball.twist_axis).swing;
  const double angle = 2.0 * std::atan2(swing.vec().norm(), swing.w());
  const Vec3 r = swing.vec().norm() > 0 ? Vec3(angle * swing.vec().normalized()) : Vec3::Zero();
  return Eigen::Vector2d(r.dot(ball.swing_axis), r.dot(ball.twist_axis.cross(ball.swing_axis)));
}

TEST(EllipticalBallLimit, WithEqualHalfAnglesItIsTheCircularCone) {
  std::mt19937_64 rng(100);
  for (int i = 0; i < 2000; ++i) {
    const BallLimit circle = random_ball(rng);
    BallLimit ellipse = circle;
    ellipse.swing_axis = circle.twist_axis.cross(random_axis(rng)).normalized();
    ellipse.swing_angle_2 = circle.swing_angle;
    const Quat q = random_rotation(rng);
    EXPECT_LT(rotation_gap(constrain(ellipse, q), constrain(circle, q)), 1e-12) << i;
    EXPECT_NEAR(violation(ellipse, q), violation(circle, q), 1e-12) << i;
  }
}

TEST(EllipticalBallLimit, ConstrainedIsInsideUnitAndIdempotent) {
  std::mt19937_64 rng(101);
  for (int i = 0; i < 5000; ++i) {
    const BallLimit ball = random_elliptical_ball(rng);
    ASSERT_FALSE(ball.validate());
    const Quat q = random_rotation(rng);
    const Quat c = constrain(ball, q);
    EXPECT_NEAR(c.norm(), 1.0, 1e-15);
    EXPECT_EQ(violation(ball, c), 0.0) << i;
    EXPECT_TRUE(same_bits(constrain(ball, c), c)) << i;
    EXPECT_LE(rotation_angle_between(q, c), violation(ball, q) + 1e-12) << i;
  }
}

TEST(EllipticalBallLimit, InsideRotationsAreReturnedBitForBit) {
  std::mt19937_64 rng(102);
  for (int i = 0; i < 2000; ++i) {
    const BallLimit ball = random_elliptical_ball(rng);
    const double rho = uniform(rng, 0.0, 0.999), phi = uniform(rng, -kPi, kPi);
    const Vec3 r =
        rho * std::cos(phi) * ball.swing_angle * ball.swing_axis +
        rho * std::sin(phi) * *ball.swing_angle_2 * ball.twist_axis.cross(ball.swing_axis);
    const Quat swing = r.norm() > 0 ? about(r.norm(), r.normalized()) : Quat::Identity();
    const Quat inside =
        swing * about(uniform(rng, ball.min_twist, ball.max_twist), ball.twist_axis);
    EXPECT_EQ(violation(ball, inside), 0.0) << i;
    EXPECT_TRUE(same_bits(constrain(ball, inside), inside)) << i;
  }
}

// The sense in which an elliptical swing is nearest: its rotation vector is the point of the
// ellipse nearest to q's swing's rotation vector.
TEST(EllipticalBallLimit, TheSwingGoesToTheNearestPointOfTheEllipse) {
  std::mt19937_64 rng(103);
  for (int i = 0; i < 1000; ++i) {
    const BallLimit ball = random_elliptical_ball(rng);
    const Quat q = random_rotation(rng);
    const Eigen::Vector2d r = swing_vector(ball, q);
    const Eigen::Vector2d kept = swing_vector(ball, constrain(ball, q));
    const double a = ball.swing_angle, b = *ball.swing_angle_2;
    EXPECT_LE(std::hypot(a > 0 ? kept.x() / a : 0.0, b > 0 ? kept.y() / b : 0.0), 1.0 + 1e-9);
    const double best = (r - kept).norm();
    for (int k = 0; k < 360; ++k) {
      const double phi = 2.0 * kPi * k / 360.0;
      const Eigen::Vector2d edge(a * std::cos(phi), b * std::sin(phi));
      ASSERT_GE((r - edge).norm(), best - 1e-9) << i;
    }
  }
}

TEST(EllipticalBallLimit, ClampsEachSwingAxisToItsOwnHalfAngle) {
  BallLimit ball{Vec3::UnitY(), 1.0, -kPi, kPi};
  ball.swing_axis = Vec3::UnitX();
  ball.swing_angle_2 = 0.3;  // about z
  const Quat about_x = about(0.9, Vec3::UnitX());
  EXPECT_TRUE(same_bits(constrain(ball, about_x), about_x));
  EXPECT_LT(rotation_gap(constrain(ball, about(0.8, Vec3::UnitZ())), about(0.3, Vec3::UnitZ())),
            1e-12);
  EXPECT_NEAR(violation(ball, about(0.8, Vec3::UnitZ())), 0.5, 1e-12);
  BallLimit bad = ball;
  bad.swing_axis = Vec3::UnitY();
  EXPECT_EQ(bad.validate()->message,
            "ball swing axis is not perpendicular to the twist axis (cosine 1)");
  bad = ball;
  bad.swing_angle_2 = 4.0;
  EXPECT_EQ(bad.validate()->message, "ball swing cone half-angle 4 rad is not within [0, pi]");
}

}  // namespace
}  // namespace animkit
