// Limit pushes (limit_push.cpp): the twist rate against finite differences of swing_twist, the
// rotation vector round trip, and push axes that point back inside the limit, on seeded random
// rotations and ball and hinge limits.
#include "../../src/kinematics/limit_push.h"

#include <gtest/gtest.h>

#include <random>

#include "limit_samples.h"

namespace animkit {
namespace {

using limit_samples::random_axis;
using limit_samples::random_ball;
using limit_samples::random_hinge;
using limit_samples::random_rotation;
using limit_samples::uniform;

TEST(LimitPush, TwistRateMatchesFiniteDifferences) {
  std::mt19937_64 rng(1);
  for (int t = 0; t < 2000; ++t) {
    const Vec3 a = random_axis(rng);
    const Quat q = random_rotation(rng);
    const Vec3 b = q * a;
    if (a.dot(b) < -0.9) continue;  // near a half-turn swing the twist is ill-conditioned
    const Vec3 w = random_axis(rng);
    const double h = 1e-6;
    auto twist = [&](double s) {
      return twist_angle(swing_twist(from_rotation_vector(s * w) * q, a).twist, a);
    };
    const double numeric = (twist(h) - twist(-h)) / (2.0 * h);
    EXPECT_NEAR(w.dot(twist_rate_axis(a, b)), numeric, 1e-5) << "trial " << t;
  }
}

TEST(LimitPush, RotationVectorRoundTrips) {
  std::mt19937_64 rng(2);
  for (int t = 0; t < 1000; ++t) {
    const Vec3 r = uniform(rng, 0.0, 3.1) * random_axis(rng);
    EXPECT_LE((rotation_vector(from_rotation_vector(r)) - r).norm(), 1e-12);
  }
  EXPECT_EQ(rotation_vector(Quat::Identity()), Vec3::Zero());
}

// Turning the wanted rotation a little about each push axis reduces its violation: the axes
// point inward, and a ball's twist axis does not change its swing to first order.
TEST(LimitPush, AxesPointBackInside) {
  std::mt19937_64 rng(3);
  int checked = 0;
  for (int t = 0; t < 3000; ++t) {
    const JointLimit limit = t % 2 ? JointLimit(random_ball(rng)) : JointLimit(random_hinge(rng));
    const Quat rest = random_rotation(rng);
    const Quat wanted = random_rotation(rng);
    const Quat rel = rest.conjugate() * wanted;
    const double before = violation(limit, rel);
    if (before < 1e-3) continue;
    const Quat local = rest * constrain(limit, rel);
    const auto axes = limit_push_axes(limit, rest, wanted, local);
    for (const Vec3& axis : axes) {
      if (axis.isZero()) continue;
      EXPECT_NEAR(axis.norm(), 1.0, 1e-12);
      const Quat turned = from_rotation_vector(1e-5 * axis) * wanted;
      EXPECT_LT(violation(limit, rest.conjugate() * turned), before) << "trial " << t;
      ++checked;
    }
    EXPECT_TRUE(at_limit(limit, rest, local, axes[0]) || at_limit(limit, rest, local, axes[1]))
        << "trial " << t;
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace animkit
