#include "animkit/core/quaternion_math.h"

#include <gtest/gtest.h>

#include <vector>

#include <cmath>
#include <numbers>
#include <random>

namespace animkit {
namespace {

TEST(ShortestArc, TurnsFromOntoToForRandomVectors) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 from(u(rng), u(rng), u(rng)), to(u(rng), u(rng), u(rng));
    const Quat q = shortest_arc(from, to);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    EXPECT_LT(((q * from).normalized() - to.normalized()).norm(), 1e-14);
    // Shortest: the rotation angle equals the angle between the vectors.
    const double angle = std::atan2(from.cross(to).norm(), from.dot(to));
    EXPECT_NEAR(rotation_angle_between(Quat::Identity(), q), angle, 1e-12);
  }
}

TEST(ShortestArc, StaysExactForTinyAngles) {
  // glm::rotation returns identity below ~5e-4 rad in float, which stalls CCD; ours must not.
  for (double angle : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const Vec3 from(0.0, -1.0, 0.0);
    const Vec3 to(std::sin(angle), -std::cos(angle), 0.0);
    const Quat q = shortest_arc(from, to);
    EXPECT_NEAR(rotation_angle_between(Quat::Identity(), q), angle, angle * 1e-9);
    EXPECT_LT((q * from - to).norm(), 1e-15);
  }
}

TEST(ShortestArc, OppositeVectorsTurnByPiAboutAPerpendicularAxis) {
  for (const Vec3& from : {Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0.3, -0.2, 0.9)}) {
    const Quat q = shortest_arc(from, -from);
    EXPECT_NEAR(q.norm(), 1.0, 1e-15);
    EXPECT_NEAR(std::abs(q.vec().dot(from.normalized())), 0.0, 1e-15);
    EXPECT_LT((q * from + from).norm(), 1e-14);
  }
}

TEST(ShortestArc, ParallelVectorsGiveIdentity) {
  const Quat q = shortest_arc(Vec3(0, 2, 0), Vec3(0, 0.5, 0));
  EXPECT_EQ(q.coeffs(), Quat::Identity().coeffs());
}

TEST(RotationAngleBetween, IgnoresQuaternionSign) {
  const Quat a(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
  const Quat b(Eigen::AngleAxisd(0.5, Vec3::UnitZ()));
  Quat minus_b = b;
  minus_b.coeffs() *= -1.0;
  EXPECT_NEAR(rotation_angle_between(a, b), 0.2, 1e-15);
  EXPECT_NEAR(rotation_angle_between(a, minus_b), 0.2, 1e-15);
}

TEST(PerpendicularAxis, IsUnitAndPerpendicular) {
  for (const Vec3& v : {Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, -3), Vec3(1, 1, 1)}) {
    const Vec3 axis = perpendicular_axis(v);
    EXPECT_NEAR(axis.norm(), 1.0, 1e-15);
    EXPECT_NEAR(axis.dot(v), 0.0, 1e-15);
  }
}

}  // namespace
}  // namespace animkit

namespace animkit {
namespace {

TEST(LargestRotationChange, IsTheLargestAngleBetweenMatchingRotations) {
  const std::vector<Quat> before{Quat::Identity(), Quat(Eigen::AngleAxisd(0.3, Vec3::UnitX())),
                                 Quat(Eigen::AngleAxisd(1.0, Vec3::UnitZ()))};
  std::vector<Quat> after = before;
  EXPECT_EQ(largest_rotation_change(before, after), 0.0);
  after[1] = Quat(Eigen::AngleAxisd(0.8, Vec3::UnitX()));
  after[2] = Quat(Eigen::AngleAxisd(1.2, Vec3::UnitZ()));
  EXPECT_NEAR(largest_rotation_change(before, after), 0.5, 1e-12);
  after[0] = Quat(-1, 0, 0, 0);  // the identity again, sign flipped: no turn
  EXPECT_NEAR(largest_rotation_change(before, after), 0.5, 1e-12);
  EXPECT_EQ(largest_rotation_change({}, {}), 0.0);
}

}  // namespace
}  // namespace animkit
