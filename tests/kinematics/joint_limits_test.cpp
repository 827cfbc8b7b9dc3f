// Joint limits: the swing-twist decomposition recomposes, constrain() lands inside, keeps
// inside rotations bit for bit, is idempotent, and is the nearest rotation for a hinge (for a
// ball: the nearest bone direction), on thousands of seeded random rotations.
#include "animkit/kinematics/joint_limits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "animkit/core/quaternion_math.h"
#include "limit_samples.h"

namespace animkit {
namespace {

using namespace limit_samples;

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
