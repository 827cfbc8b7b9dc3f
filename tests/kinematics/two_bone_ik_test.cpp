// The analytic two-bone solver: exact where the target is reachable, bone lengths kept, the
// middle joint on the pole's side, straight at the target where unreachable, finite in the
// degenerate cases, on thousands of seeded random limbs.
#include "animkit/kinematics/two_bone_ik.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace animkit {
namespace {

Vec3 random_direction(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return Vec3(n(rng), n(rng), n(rng)).normalized();
}

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

struct Limb {
  TwoBoneInput input;
  double l1 = 0, l2 = 0;
};

// A random bent limb; the target at `fraction` of the way from the shortest reach to the
// longest (outside [0, 1]: unreachable), the pole anywhere nearby.
Limb random_limb(std::mt19937_64& rng, double fraction) {
  Limb limb;
  limb.l1 = uniform(rng, 0.1, 2.0);
  limb.l2 = uniform(rng, 0.1, 2.0);
  TwoBoneInput& in = limb.input;
  in.root = Vec3(uniform(rng, -3, 3), uniform(rng, -3, 3), uniform(rng, -3, 3));
  in.middle = in.root + limb.l1 * random_direction(rng);
  in.end = in.middle + limb.l2 * random_direction(rng);
  const double lo = std::abs(limb.l1 - limb.l2), hi = limb.l1 + limb.l2;
  in.target = in.root + (lo + fraction * (hi - lo)) * random_direction(rng);
  in.pole = in.root + uniform(rng, 0.5, 3.0) * random_direction(rng);
  return limb;
}

// The pole's offset from the root->target line, normalized.
Vec3 pole_side(const TwoBoneInput& in) {
  const Vec3 u = (in.target - in.root).normalized();
  const Vec3 p = in.pole - in.root;
  return (p - p.dot(u) * u).normalized();
}

TEST(TwoBoneIk, ReachesEveryReachableTargetExactlyWithTheKneeOnThePoleSide) {
  std::mt19937_64 rng(2024);
  for (int i = 0; i < 5000; ++i) {
    const Limb limb = random_limb(rng, uniform(rng, 0.001, 0.999));
    const TwoBoneInput& in = limb.input;
    const auto r = solve_two_bone(in);
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(r->reached) << i;
    EXPECT_LT(r->error, 1e-9) << i;
    EXPECT_LT((r->end - in.target).norm(), 1e-9) << i;
    EXPECT_NEAR((r->middle - in.root).norm(), limb.l1, 1e-12) << i;
    EXPECT_NEAR((r->end - r->middle).norm(), limb.l2, 1e-12) << i;
    EXPECT_NEAR(r->upper_rotation.norm(), 1.0, 1e-15);
    EXPECT_NEAR(r->lower_rotation.norm(), 1.0, 1e-15);
    // The rotations are what moved the joints, to a few units in the last place (the rounding
    // differs between CPUs with and without AVX-512 under -march=native).
    EXPECT_LT((in.root + r->upper_rotation * (in.middle - in.root) - r->middle).norm(), 4e-15);
    // The middle joint lies in the plane of root, target and pole, on the pole's side.
    const Vec3 side = pole_side(in);
    const Vec3 normal = (in.target - in.root).cross(side).normalized();
    EXPECT_NEAR((r->middle - in.root).dot(normal), 0.0, 1e-12) << i;
    EXPECT_GT((r->middle - in.root).dot(side), 0.0) << i;
    // The knee stays a hinge: both bones turn the old bend normal onto the same new normal.
    const Vec3 bend = (in.middle - in.root).cross(in.end - in.middle).normalized();
    EXPECT_LT((r->upper_rotation * bend - r->lower_rotation * bend).norm(), 1e-12) << i;
  }
}

TEST(TwoBoneIk, ReachesTheEndsOfTheReachExactly) {
  std::mt19937_64 rng(7);
  for (double fraction : {0.0, 1.0}) {
    for (int i = 0; i < 500; ++i) {
      const Limb limb = random_limb(rng, fraction);
      const auto r = solve_two_bone(limb.input);
      ASSERT_TRUE(r);
      EXPECT_LT(r->error, 1e-9) << i;
    }
  }
}

TEST(TwoBoneIk, UnreachableTargetsGetTheLimbStraightAlongTheLine) {
  std::mt19937_64 rng(99);
  for (int i = 0; i < 2000; ++i) {
    const bool far = i % 2 == 0;
    Limb limb = random_limb(rng, far ? uniform(rng, 1.01, 3.0) : 0.5);
    TwoBoneInput& in = limb.input;
    const double lo = std::abs(limb.l1 - limb.l2), hi = limb.l1 + limb.l2;
    if (!far) {
      if (lo < 1e-3) continue;  // equal bones reach every near target
      in.target = in.root + uniform(rng, 0.01, 0.99) * lo * (in.target - in.root).normalized();
    }
    const auto r = solve_two_bone(in);
    ASSERT_TRUE(r);
    EXPECT_FALSE(r->reached) << i;
    const Vec3 u = (in.target - in.root).normalized();
    const double reach = far ? hi : lo;
    EXPECT_LT((r->end - (in.root + reach * u)).norm(), 1e-12) << i;
    EXPECT_NEAR(r->error, std::abs((in.target - in.root).norm() - reach), 1e-12) << i;
    // Straight: the middle joint is on the root-target line too.
    const Vec3 m = r->middle - in.root;
    EXPECT_LT((m - m.dot(u) * u).norm(), 1e-12) << i;
  }
}

TEST(TwoBoneIk, AnAlreadySolvedLimbIsNotMoved) {
  TwoBoneInput in{Vec3(0, 1, 0), Vec3(0, 0.5, 0.1), Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0.5, 2)};
  const auto r = solve_two_bone(in);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->reached);
  EXPECT_LT(r->upper_rotation.angularDistance(Quat::Identity()), 1e-12);
  EXPECT_LT(r->lower_rotation.angularDistance(Quat::Identity()), 1e-12);
}

TEST(TwoBoneIk, APoleOnTheTargetLineKeepsTheCurrentBendPlane) {
  // Bent toward +y in the plane z = 0; the pole sits on the root->target line (the x axis).
  TwoBoneInput in{Vec3(0, 0, 0), Vec3(0.5, 0.5, 0), Vec3(1, 0, 0), Vec3(1.2, 0, 0), Vec3(3, 0, 0)};
  const auto r = solve_two_bone(in);
  ASSERT_TRUE(r);
  EXPECT_LT(r->error, 1e-12);
  EXPECT_GT(r->middle.y(), 0.1);
  EXPECT_NEAR(r->middle.z(), 0.0, 1e-15);
}

TEST(TwoBoneIk, DegenerateCasesStayFinite) {
  const auto finite = [](const TwoBoneResult& r) {
    return r.upper_rotation.coeffs().allFinite() && r.lower_rotation.coeffs().allFinite() &&
           r.middle.allFinite() && r.end.allFinite() && std::isfinite(r.error);
  };
  // Target exactly at the root with equal bones: reachable by folding.
  TwoBoneInput in{Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(0, 0, 0), Vec3(0, 0, 1)};
  auto r = solve_two_bone(in);
  ASSERT_TRUE(r);
  EXPECT_TRUE(finite(*r));
  EXPECT_TRUE(r->reached);
  EXPECT_LT(r->error, 1e-12);
  // Unequal bones, target at the root: folded, as near as it gets.
  in.end = Vec3(0.5, 1, 0);
  r = solve_two_bone(in);
  ASSERT_TRUE(r);
  EXPECT_TRUE(finite(*r));
  EXPECT_FALSE(r->reached);
  EXPECT_NEAR(r->error, 0.5, 1e-12);
  // Everything on one line: a straight limb, the pole on the line, the target on it too.
  in = TwoBoneInput{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0), Vec3(1.5, 0, 0), Vec3(4, 0, 0)};
  r = solve_two_bone(in);
  ASSERT_TRUE(r);
  EXPECT_TRUE(finite(*r));
  EXPECT_TRUE(r->reached);
  EXPECT_LT(r->error, 1e-12);
  // A straight limb folded back on itself, pole at the root, target behind it.
  in = TwoBoneInput{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, 0), Vec3(-0.7, 0, 0), Vec3(0, 0, 0)};
  r = solve_two_bone(in);
  ASSERT_TRUE(r);
  EXPECT_TRUE(finite(*r));
  EXPECT_TRUE(r->reached);
  EXPECT_LT(r->error, 1e-12);
}

TEST(TwoBoneIk, InvalidInputIsNamed) {
  TwoBoneInput in{Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  EXPECT_EQ(solve_two_bone(in).error().message,
            "two-bone upper bone (root to middle) has zero length");
  in.middle = Vec3(1, 0, 0);
  EXPECT_EQ(solve_two_bone(in).error().message,
            "two-bone lower bone (middle to end) has zero length");
  in.end = Vec3(2, 0, 0);
  in.target = Vec3(NAN, 0, 0);
  EXPECT_EQ(solve_two_bone(in).error().message,
            "two-bone target has a non-finite coordinate (nan, 0, 0)");
  in.target = Vec3(1, 1, 0);
  EXPECT_EQ(solve_two_bone(in, TwoBoneSettings{0.0}).error().message,
            "two-bone degenerate_length must be positive and finite, got 0");
  EXPECT_TRUE(solve_two_bone(in));
}

}  // namespace
}  // namespace animkit
