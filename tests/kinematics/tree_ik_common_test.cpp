// The pieces the tree solvers share (src/kinematics/tree_ik_common.h): the weighted best-fit
// rotation (Wahba's problem) against rotations known in advance, its rank-one and hinge
// cases, and the effector bookkeeping.
#include "../../src/kinematics/tree_ik_common.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "animkit/core/quaternion_math.h"
#include "limit_samples.h"
#include "tree_ik_samples.h"

namespace animkit {
namespace {

using limit_samples::kPi;
using limit_samples::random_axis;
using limit_samples::random_rotation;
using limit_samples::rotation_gap;
using limit_samples::uniform;

TEST(AboutAxisToward, IsTheRotationByAtan2OfTheSineAndCosine) {
  std::mt19937_64 rng(4);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 axis = random_axis(rng);
    const double angle = uniform(rng, -kPi, kPi), scale = uniform(rng, 1e-3, 1e3);
    const double sine = scale * std::sin(angle), cosine = scale * std::cos(angle);
    const Quat expected(Eigen::AngleAxisd(std::atan2(sine, cosine), axis));
    EXPECT_LE(rotation_gap(detail::about_axis_toward(sine, cosine, axis), expected), 1e-14) << k;
    EXPECT_NEAR(detail::about_axis_toward(sine, cosine, axis).norm(), 1.0, 1e-15);
  }
  const Vec3 z = Vec3::UnitZ();
  EXPECT_TRUE(detail::about_axis_toward(0.0, 0.0, z).coeffs() == Quat::Identity().coeffs());
  EXPECT_TRUE(detail::about_axis_toward(0.0, 2.0, z).coeffs() == Quat::Identity().coeffs());
  EXPECT_LE(rotation_gap(detail::about_axis_toward(0.0, -2.0, z), Quat(0, 0, 0, 1)), 1e-15);
}

TEST(BestFitRotation, RecoversTheRotationThatMapsThePairs) {
  std::mt19937_64 rng(1);
  for (int k = 0; k < 1000; ++k) {
    const Quat truth = random_rotation(rng);
    detail::BestFitRotation fit;
    const int pairs = 2 + k % 4;
    for (int m = 0; m < pairs; ++m) {
      const Vec3 u = random_axis(rng) * uniform(rng, 0.1, 2.0);
      fit.add(u, truth * u, uniform(rng, 0.1, 3.0));
    }
    EXPECT_EQ(fit.count(), pairs);
    EXPECT_LE(rotation_gap(fit.rotation(), truth), 1e-9) << k;
  }
}

TEST(BestFitRotation, NoisyPairsGiveTheLeastSquaresRotation) {
  // The optimum: no small turn about any axis lowers sum w |R u - v|^2.
  std::mt19937_64 rng(2);
  for (int k = 0; k < 200; ++k) {
    std::vector<Vec3> from, to;
    std::vector<double> weight;
    detail::BestFitRotation fit;
    for (int m = 0; m < 4; ++m) {
      from.push_back(random_axis(rng));
      to.push_back(random_axis(rng) * uniform(rng, 0.5, 1.5));
      weight.push_back(uniform(rng, 0.1, 2.0));
      fit.add(from.back(), to.back(), weight.back());
    }
    const auto cost = [&](const Quat& r) {
      double sum = 0.0;
      for (std::size_t m = 0; m < from.size(); ++m)
        sum += weight[m] * (r * from[m] - to[m]).squaredNorm();
      return sum;
    };
    const Quat best = fit.rotation();
    for (int t = 0; t < 20; ++t) {
      const Quat nudged = Quat(Eigen::AngleAxisd(1e-3, random_axis(rng))) * best;
      EXPECT_GE(cost(nudged), cost(best) - 1e-12) << k;
    }
  }
}

TEST(BestFitRotation, OnePairOrOneLineIsTheShortestArc) {
  const Vec3 u(1, 2, 3), v(-2, 0.5, 1);
  detail::BestFitRotation one;
  one.add(u, v, 2.0);
  EXPECT_LE(rotation_gap(one.rotation(), shortest_arc(u, v)), 1e-15);
  detail::BestFitRotation line;  // every pair along the same two lines
  line.add(u, v, 1.0);
  line.add(2.0 * u, 3.0 * v, 0.5);
  line.add(Vec3::Zero(), v, 1.0);  // no direction: skipped
  EXPECT_EQ(line.count(), 2);
  EXPECT_LE(rotation_gap(line.rotation(), shortest_arc(u, v)), 1e-12);
  EXPECT_TRUE(detail::BestFitRotation{}.rotation().coeffs() == Quat::Identity().coeffs());
}

TEST(BestFitRotation, AboutAnAxisIsTheBestTurnAboutIt) {
  std::mt19937_64 rng(3);
  for (int k = 0; k < 200; ++k) {
    const Vec3 axis = random_axis(rng);
    detail::BestFitRotation fit;
    std::vector<Vec3> from, to;
    for (int m = 0; m < 3; ++m) {
      from.push_back(random_axis(rng));
      to.push_back(random_axis(rng));
      fit.add(from.back(), to.back(), 1.0);
    }
    const Quat r = fit.rotation_about(axis);
    EXPECT_LE(std::abs(r.vec().normalized().cross(axis).norm()), 1e-9);
    const auto cost = [&](const Quat& q) {
      double sum = 0.0;
      for (std::size_t m = 0; m < from.size(); ++m) sum += (q * from[m] - to[m]).squaredNorm();
      return sum;
    };
    for (const double step : {-1e-3, 1e-3, -0.5, 0.5, 3.0}) {
      EXPECT_GE(cost(Quat(Eigen::AngleAxisd(step, axis)) * r), cost(r) - 1e-12) << k;
    }
  }
}

TEST(TreeIkCommon, EffectorWeightsSumUpTheTree) {
  const Skeleton s = tree_samples::figure();
  const int hand = s.find_joint("l_hand"), foot = s.find_joint("r_foot");
  const int chest = s.find_joint("chest"), elbow = s.find_joint("l_elbow");
  const std::vector<Effector> effectors{Effector{hand, Vec3::Zero(), std::nullopt, 2.0},
                                        Effector{foot, Vec3::Zero(), std::nullopt, 0.5},
                                        Effector{chest, Vec3::Zero(), std::nullopt, 1.0}};
  TreeIkScratch scratch;
  EXPECT_FALSE(scratch.fits(s.joint_count()));
  scratch.resize(s.joint_count());
  EXPECT_TRUE(scratch.fits(s.joint_count()));
  detail::index_effectors(s, effectors, scratch);
  EXPECT_EQ(scratch.effector_of[static_cast<std::size_t>(hand)], 0);
  EXPECT_EQ(scratch.effector_of[static_cast<std::size_t>(chest)], 2);
  EXPECT_EQ(scratch.effector_of[static_cast<std::size_t>(elbow)], -1);
  EXPECT_EQ(scratch.subtree_weight[0], 3.5);
  EXPECT_EQ(scratch.below_weight[0], 3.5);
  EXPECT_EQ(scratch.subtree_weight[static_cast<std::size_t>(chest)], 3.0);
  EXPECT_EQ(scratch.below_weight[static_cast<std::size_t>(chest)], 2.0);
  EXPECT_EQ(scratch.below_weight[static_cast<std::size_t>(hand)], 0.0);
  EXPECT_EQ(scratch.subtree_weight[static_cast<std::size_t>(s.find_joint("head"))], 0.0);
}

}  // namespace
}  // namespace animkit
