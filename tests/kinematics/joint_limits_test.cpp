// Joint limits: the swing-twist decomposition recomposes, constrain() lands inside, keeps
// inside rotations bit for bit, is idempotent, and is the nearest rotation for a hinge (for a
// ball: the nearest bone direction), on thousands of seeded random rotations.
#include "animkit/kinematics/joint_limits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "animkit/core/quaternion_math.h"

namespace animkit {
namespace {

constexpr double kPi = std::numbers::pi;

Quat random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  Quat q(n(rng), n(rng), n(rng), n(rng));
  return q.normalized();
}

Vec3 random_axis(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Quat about(double angle, const Vec3& axis) {
  return Quat(Eigen::AngleAxisd(angle, axis));
}

HingeLimit random_hinge(std::mt19937_64& rng) {
  double a = uniform(rng, -kPi, kPi), b = uniform(rng, -kPi, kPi);
  return HingeLimit{random_axis(rng), std::min(a, b), std::max(a, b)};
}

BallLimit random_ball(std::mt19937_64& rng) {
  double a = uniform(rng, -kPi, kPi), b = uniform(rng, -kPi, kPi);
  return BallLimit{random_axis(rng), uniform(rng, 0.0, kPi), std::min(a, b), std::max(a, b)};
}

bool same_bits(const Quat& a, const Quat& b) {
  return a.coeffs() == b.coeffs();
}

// Same rotation: q or -q, coefficient by coefficient.
double rotation_gap(const Quat& a, const Quat& b) {
  return std::min((a.coeffs() - b.coeffs()).norm(), (a.coeffs() + b.coeffs()).norm());
}

TEST(SwingTwist, RecomposesWithTwistAboutTheAxisAndSwingPerpendicular) {
  std::mt19937_64 rng(12);
  for (int i = 0; i < 5000; ++i) {
    const Quat q = random_rotation(rng);
    const Vec3 axis = random_axis(rng);
    const SwingTwist st = swing_twist(q, axis);
    EXPECT_LT(rotation_gap(st.swing * st.twist, q), 1e-14) << i;
    EXPECT_NEAR(st.swing.norm(), 1.0, 1e-15);
    EXPECT_NEAR(st.twist.norm(), 1.0, 1e-15);
    EXPECT_LT(st.twist.vec().cross(axis).norm(), 1e-15) << i;
    EXPECT_LT(std::abs(st.swing.vec().dot(axis)), 1e-15) << i;
    EXPECT_GE(st.swing.w(), 0.0);
    EXPECT_GE(st.twist.w(), 0.0);
    const SwingTwist negated = swing_twist(Quat(-q.coeffs()), axis);
    EXPECT_TRUE(same_bits(negated.swing, st.swing) && same_bits(negated.twist, st.twist)) << i;
  }
}

TEST(SwingTwist, RecoversAKnownSwingAndTwist) {
  const Vec3 axis = Vec3::UnitY();
  const SwingTwist st = swing_twist(about(0.7, Vec3::UnitX()) * about(-0.4, axis), axis);
  EXPECT_NEAR(twist_angle(st.twist, axis), -0.4, 1e-15);
  EXPECT_LT(rotation_gap(st.swing, about(0.7, Vec3::UnitX())), 1e-15);
}

TEST(SwingTwist, AHalfTurnSwingHasNoTwistAndStaysFinite) {
  const Vec3 axis = Vec3::UnitZ();
  const Quat half_turn(0.0, 1.0, 0.0, 0.0);  // pi about x, perpendicular to the axis
  SwingTwist st = swing_twist(half_turn, axis);
  EXPECT_TRUE(same_bits(st.twist, Quat::Identity()));
  EXPECT_LT(rotation_gap(st.swing, half_turn), 1e-15);
  // Just short of a half turn the twist is still recovered, and -q agrees.
  const Quat q = about(kPi - 1e-9, Vec3::UnitY()) * about(0.3, axis);
  st = swing_twist(q, axis);
  EXPECT_NEAR(twist_angle(st.twist, axis), 0.3, 1e-6);
  EXPECT_LT(rotation_gap(st.swing * st.twist, q), 1e-15);
  st = swing_twist(Quat(-q.coeffs()), axis);
  EXPECT_NEAR(twist_angle(st.twist, axis), 0.3, 1e-6);
}

TEST(HingeLimit, ConstrainedIsAnInsideRotationAboutTheAxisAndIdempotent) {
  std::mt19937_64 rng(34);
  for (int i = 0; i < 5000; ++i) {
    const HingeLimit hinge = random_hinge(rng);
    const Quat q = random_rotation(rng);
    const Quat c = constrain(hinge, q);
    EXPECT_NEAR(c.norm(), 1.0, 1e-15);
    EXPECT_LT(c.vec().cross(hinge.axis).norm(), 1e-15) << i;
    EXPECT_EQ(violation(hinge, c), 0.0) << i;
    EXPECT_TRUE(same_bits(constrain(hinge, c), c)) << i;
    EXPECT_NEAR(violation(hinge, q), rotation_angle_between(q, c), 1e-15);
    EXPECT_GT(violation(hinge, q), 0.0);  // a random rotation is never exactly about the axis
  }
}

TEST(HingeLimit, InsideRotationsAreReturnedBitForBit) {
  std::mt19937_64 rng(56);
  for (int i = 0; i < 2000; ++i) {
    const HingeLimit hinge = random_hinge(rng);
    const Quat inside = about(uniform(rng, hinge.min_angle, hinge.max_angle), hinge.axis);
    EXPECT_EQ(violation(hinge, inside), 0.0) << i;
    EXPECT_TRUE(same_bits(constrain(hinge, inside), inside)) << i;
  }
}

TEST(HingeLimit, NoSampledInsideRotationIsNearerThanTheConstrainedOne) {
  std::mt19937_64 rng(78);
  for (int i = 0; i < 1000; ++i) {
    const HingeLimit hinge = random_hinge(rng);
    const Quat q = random_rotation(rng);
    const double best = rotation_angle_between(q, constrain(hinge, q));
    for (int k = 0; k <= 100; ++k) {
      const double angle = hinge.min_angle + (hinge.max_angle - hinge.min_angle) * k / 100.0;
      ASSERT_GE(rotation_angle_between(q, about(angle, hinge.axis)), best - 1e-12) << i;
    }
  }
}

TEST(HingeLimit, ClampsTheShortWayRoundTheCircle) {
  const HingeLimit hinge{Vec3::UnitZ(), -0.5, 2.5};
  // 3.0 rad is 0.5 past the maximum; -3.0 rad (= 3.28 rad) is 0.78 past it but 2.5 short of
  // the minimum the other way: the maximum is nearer for both.
  EXPECT_LT(rotation_gap(constrain(hinge, about(3.0, Vec3::UnitZ())), about(2.5, Vec3::UnitZ())),
            1e-15);
  EXPECT_LT(rotation_gap(constrain(hinge, about(-3.0, Vec3::UnitZ())), about(2.5, Vec3::UnitZ())),
            1e-15);
  EXPECT_LT(rotation_gap(constrain(hinge, about(-1.0, Vec3::UnitZ())), about(-0.5, Vec3::UnitZ())),
            1e-15);
  EXPECT_NEAR(violation(hinge, about(3.0, Vec3::UnitZ())), 0.5, 1e-14);
  // A rotation about another axis projects onto the hinge's axis: the twist part is kept.
  const Quat bent = about(0.4, Vec3::UnitX()) * about(1.0, Vec3::UnitZ());
  EXPECT_LT(rotation_gap(constrain(hinge, bent), about(1.0, Vec3::UnitZ())), 1e-15);
}

TEST(BallLimit, ConstrainedIsInsideUnitAndIdempotent) {
  std::mt19937_64 rng(90);
  for (int i = 0; i < 5000; ++i) {
    const BallLimit ball = random_ball(rng);
    const Quat q = random_rotation(rng);
    const Quat c = constrain(ball, q);
    EXPECT_NEAR(c.norm(), 1.0, 1e-15);
    EXPECT_EQ(violation(ball, c), 0.0) << i;
    EXPECT_TRUE(same_bits(constrain(ball, c), c)) << i;
    // The distance moved is bounded by the excess violation() reports.
    EXPECT_LE(rotation_angle_between(q, c), violation(ball, q) + 1e-12) << i;
  }
}

// Near a half-turn swing the twist is ill-conditioned: a cone at or just short of pi keeps such
// swings, and constrain() must still land inside and be idempotent there (elliptical cones too).
TEST(BallLimit, IdempotentForSwingsNearAHalfTurn) {
  std::mt19937_64 rng(93);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 axis = random_axis(rng);
    const double cone = i % 3 == 0 ? kPi : kPi - std::pow(10.0, uniform(rng, -9, -1));
    BallLimit ball{axis, cone, -0.1, 0.1};
    const Vec3 swing_axis = axis.cross(random_axis(rng)).normalized();
    if (i % 2 == 0) {  // elliptical, one half-angle at or near pi too
      ball.swing_axis = axis.cross(random_axis(rng)).normalized();
      ball.swing_angle_2 = uniform(rng, 0.0, kPi);
    }
    const Quat q = about(kPi - std::pow(10.0, uniform(rng, -10, -1)), swing_axis) *
                   about(uniform(rng, -3, 3), axis);
    const Quat c = constrain(ball, q);
    ASSERT_TRUE(c.coeffs().allFinite());
    EXPECT_EQ(violation(ball, c), 0.0) << i;
    EXPECT_TRUE(same_bits(constrain(ball, c), c)) << i;
  }
}

// A twist past its range by less than the slack of a near half-turn swing is inside; once the
// swing is clamped into a narrow cone that slack is gone, so the twist must be clamped too.
TEST(BallLimit, ClampingTheSwingAlsoClampsATwistThatWasInsideOnlyBySlack) {
  const BallLimit ball{Vec3::UnitY(), 1.0, -0.1, 0.1};
  const Quat q = about(kPi - 1e-10, Vec3::UnitX()) * about(0.1 + 1e-6, Vec3::UnitY());
  const Quat c = constrain(ball, q);
  EXPECT_EQ(violation(ball, c), 0.0);
  EXPECT_TRUE(same_bits(constrain(ball, c), c));
  EXPECT_LT(rotation_gap(c, about(1.0, Vec3::UnitX()) * about(0.1, Vec3::UnitY())), 1e-15);
}

TEST(BallLimit, InsideRotationsAreReturnedBitForBit) {
  std::mt19937_64 rng(91);
  for (int i = 0; i < 2000; ++i) {
    const BallLimit ball = random_ball(rng);
    const Vec3 swing_axis = ball.twist_axis.cross(random_axis(rng)).normalized();
    const Quat inside = about(uniform(rng, 0.0, ball.swing_angle), swing_axis) *
                        about(uniform(rng, ball.min_twist, ball.max_twist), ball.twist_axis);
    EXPECT_EQ(violation(ball, inside), 0.0) << i;
    EXPECT_TRUE(same_bits(constrain(ball, inside), inside)) << i;
  }
}

// What holds for a ball: the bone's direction after constrain() is the direction inside the
// cone nearest to the bone's direction under q, and the twist is the nearest in range.
TEST(BallLimit, TheBoneEndsAtTheNearestDirectionInTheCone) {
  std::mt19937_64 rng(92);
  for (int i = 0; i < 1000; ++i) {
    const BallLimit ball = random_ball(rng);
    const Quat q = random_rotation(rng);
    const Vec3 bone = q * ball.twist_axis;
    const Vec3 kept = constrain(ball, q) * ball.twist_axis;
    const double best = std::atan2(bone.cross(kept).norm(), bone.dot(kept));
    EXPECT_LE(std::acos(std::clamp(kept.dot(ball.twist_axis), -1.0, 1.0)), ball.swing_angle + 1e-9);
    for (int k = 0; k < 100; ++k) {
      const Vec3 swing_axis = ball.twist_axis.cross(random_axis(rng)).normalized();
      const Vec3 other = about(uniform(rng, 0.0, ball.swing_angle), swing_axis) * ball.twist_axis;
      ASSERT_GE(std::atan2(bone.cross(other).norm(), bone.dot(other)), best - 1e-12) << i;
    }
  }
}

TEST(BallLimit, ClampsSwingAndTwistSeparately) {
  const BallLimit ball{Vec3::UnitY(), 0.5, -0.2, 0.3};
  const Quat q = about(0.9, Vec3::UnitX()) * about(0.6, Vec3::UnitY());
  const Quat expected = about(0.5, Vec3::UnitX()) * about(0.3, Vec3::UnitY());
  EXPECT_LT(rotation_gap(constrain(ball, q), expected), 1e-15);
  EXPECT_NEAR(violation(ball, q), 0.4 + 0.3, 1e-14);
}

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

TEST(JointLimits, FreeJointsAndSpecialRotationsStayFinite) {
  const Quat specials[] = {Quat::Identity(),  Quat(0, 1, 0, 0),
                           Quat(0, 0, 1, 0),  Quat(0, 0, 0, 1),
                           Quat(-1, 0, 0, 0), Quat(0, std::sqrt(0.5), 0, std::sqrt(0.5))};
  const JointLimit limits[] = {FreeJoint{},
                               HingeLimit{Vec3::UnitY(), 0.0, 0.0},
                               HingeLimit{Vec3::UnitY(), -kPi, kPi},
                               BallLimit{Vec3::UnitY(), 0.0, 0.0, 0.0},
                               BallLimit{Vec3::UnitY(), kPi, -kPi, kPi},
                               BallLimit{Vec3::UnitY(), 1.0, -0.5, 0.5}};
  for (const JointLimit& limit : limits) {
    for (const Quat& q : specials) {
      const Quat c = constrain(limit, q);
      ASSERT_TRUE(c.coeffs().allFinite());
      EXPECT_NEAR(c.norm(), 1.0, 1e-15);
      EXPECT_EQ(violation(limit, c), 0.0);
      EXPECT_TRUE(std::isfinite(violation(limit, q)));
    }
  }
  EXPECT_TRUE(same_bits(constrain(FreeJoint{}, Quat(0, 1, 0, 0)), Quat(0, 1, 0, 0)));
}

TEST(JointLimits, ValidateNamesTheProblem) {
  EXPECT_FALSE(validate(HingeLimit{Vec3::UnitZ(), -1.0, 1.0}));
  EXPECT_FALSE(validate(FreeJoint{}));
  EXPECT_EQ(validate(HingeLimit{Vec3(0, 0, 2), 0, 1})->message,
            "hinge axis is not unit length (norm 2)");
  EXPECT_EQ(validate(HingeLimit{Vec3::UnitZ(), 1, 0.5})->message,
            "hinge angle range minimum 1 rad is above its maximum 0.5 rad");
  EXPECT_EQ(validate(HingeLimit{Vec3::UnitZ(), -4, 0})->message,
            "hinge angle range [-4, 0] rad is not within [-pi, pi]");
  EXPECT_EQ(validate(BallLimit{Vec3(NAN, 0, 0), 1, 0, 0})->message,
            "ball twist axis has a non-finite coordinate");
  EXPECT_EQ(validate(BallLimit{Vec3::UnitY(), -0.1, 0, 0})->message,
            "ball swing cone half-angle -0.1 rad is not within [0, pi]");
  EXPECT_EQ(validate(BallLimit{Vec3::UnitY(), 1, 0.2, 0.1})->message,
            "ball twist range minimum 0.2 rad is above its maximum 0.1 rad");
}

}  // namespace
}  // namespace animkit
