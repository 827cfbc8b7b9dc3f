#include "animkit/collision/collider_motion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "animkit/core/quaternion_math.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kNaN;

// Rodrigues' formula: r turned by `angle` about the unit axis k, written out independently of
// Eigen's quaternions.
Vec3 rodrigues(const Vec3& r, const Vec3& k, double angle) {
  return r * std::cos(angle) + k.cross(r) * std::sin(angle) + k * k.dot(r) * (1 - std::cos(angle));
}

ScriptedMotion spinning() {
  ScriptedMotion m;
  m.initial.position = Vec3(0.3, 1.2, -0.4);
  m.initial.rotation = Quat(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
  m.linear_velocity = Vec3(0.5, -0.25, 2.0);
  m.angular_velocity = Vec3(-0.4, 1.1, 0.6);
  return m;
}

KeyframedMotion three_keys() {
  KeyframedMotion m;
  m.keyframes = {
      {0.5, Vec3(0, 1, 0), Quat::Identity()},
      {1.5, Vec3(2, 1, 0), Quat(Eigen::AngleAxisd(1.2, Vec3::UnitY()))},
      {2.0, Vec3(2, 3, 1), Quat(Eigen::AngleAxisd(2.0, Vec3(1, 1, 0).normalized()))},
  };
  return m;
}

TEST(ColliderMotion, ScriptedMotionIsTheClosedForm) {
  const ScriptedMotion m = spinning();
  const double speed = m.angular_velocity.norm();
  const Vec3 axis = m.angular_velocity / speed;
  const Vec3 local(0.2, -0.7, 0.45);
  for (double t : {-0.8, 0.0, 0.3, 1.0, 2.5}) {
    const RigidPose pose = pose_at(m, t);
    EXPECT_TRUE(pose.position.isApprox(m.initial.position + t * m.linear_velocity, 1e-15));
    // A material point turns about the moving origin by |w| t about w.
    const Vec3 expected = pose.position + rodrigues(m.initial.rotation * local, axis, speed * t);
    EXPECT_LT((pose.to_world(local) - expected).norm(), 1e-14) << "t = " << t;
    if (speed * std::abs(t) < std::numbers::pi) {
      EXPECT_NEAR(rotation_angle_between(pose.rotation, m.initial.rotation), speed * std::abs(t),
                  1e-12);
    }
  }
}

TEST(ColliderMotion, ZeroVelocitiesStayPut) {
  ScriptedMotion m;
  m.initial.position = Vec3(1, 2, 3);
  m.initial.rotation = Quat(Eigen::AngleAxisd(0.4, Vec3::UnitZ()));
  for (double t : {-5.0, 0.0, 7.0}) {
    const RigidPose pose = pose_at(m, t);
    EXPECT_EQ(pose.position, m.initial.position);
    EXPECT_TRUE(pose.rotation.isApprox(m.initial.rotation, 1e-15));
    EXPECT_EQ(point_velocity(m, t, Vec3(4, 5, 6)), Vec3::Zero());
  }
}

TEST(ColliderMotion, KeyframesInterpolateAndClamp) {
  const KeyframedMotion m = three_keys();
  for (const Keyframe& k : m.keyframes) {
    const RigidPose pose = pose_at(m, k.time);
    EXPECT_TRUE(pose.position.isApprox(k.position, 1e-15));
    EXPECT_NEAR(rotation_angle_between(pose.rotation, k.rotation), 0.0, 1e-7);
  }
  // Halfway through a segment: the mean position and half the turn, as Eigen's slerp.
  const Keyframe& a = m.keyframes[1];
  const Keyframe& b = m.keyframes[2];
  const RigidPose half = pose_at(m, 1.75);
  EXPECT_TRUE(half.position.isApprox(0.5 * (a.position + b.position), 1e-15));
  EXPECT_NEAR(rotation_angle_between(half.rotation, a.rotation),
              0.5 * rotation_angle_between(a.rotation, b.rotation), 1e-12);
  EXPECT_NEAR(rotation_angle_between(half.rotation, a.rotation.slerp(0.5, b.rotation)), 0.0, 1e-7);
  // Before the first keyframe and after the last: their poses, at rest.
  EXPECT_EQ(pose_at(m, -3.0).position, m.keyframes.front().position);
  EXPECT_EQ(pose_at(m, 9.0).position, m.keyframes.back().position);
  EXPECT_NEAR(rotation_angle_between(pose_at(m, 9.0).rotation, b.rotation), 0.0, 1e-7);
  EXPECT_EQ(point_velocity(m, 0.1, Vec3(1, 1, 1)), Vec3::Zero());
  EXPECT_EQ(point_velocity(m, 2.0, Vec3(1, 1, 1)), Vec3::Zero());
  // At a keyframe's time the segment starting there sets the velocity.
  EXPECT_TRUE(point_velocity(m, 0.5, Vec3(0, 1, 0)).isApprox(Vec3(2, 0, 0), 1e-14));
}

TEST(ColliderMotion, SlerpTakesTheShorterArc) {
  KeyframedMotion m = three_keys();
  KeyframedMotion negated = m;
  negated.keyframes[1].rotation.coeffs() *= -1.0;  // the same rotation
  for (double t : {0.7, 1.1, 1.6, 1.9}) {
    EXPECT_NEAR(rotation_angle_between(pose_at(m, t).rotation, pose_at(negated, t).rotation), 0.0,
                1e-7);
  }
}

// d/dt of a material point's world position, by central differences, against point_velocity.
void expect_velocity_matches_difference(const ColliderMotion& motion, double t) {
  const double h = 1e-6;
  for (const Vec3& local : {Vec3(0, 0, 0), Vec3(0.4, -0.3, 0.9), Vec3(-1.5, 0.2, 0.1)}) {
    const Vec3 x = pose_at(motion, t).to_world(local);
    const Vec3 difference =
        (pose_at(motion, t + h).to_world(local) - pose_at(motion, t - h).to_world(local)) / (2 * h);
    const Vec3 v = point_velocity(motion, t, x);
    EXPECT_LT((v - difference).norm(), 1e-7 * (1 + v.norm())) << "t = " << t;
  }
}

TEST(ColliderMotion, PointVelocityIsTheTimeDerivative) {
  for (double t : {-0.5, 0.0, 0.8, 3.0}) expect_velocity_matches_difference(spinning(), t);
  for (double t : {0.6, 1.0, 1.49, 1.7, 1.95}) expect_velocity_matches_difference(three_keys(), t);
}

TEST(ColliderMotion, ValidateNamesTheFirstProblem) {
  EXPECT_FALSE(validate_motion(spinning()));
  EXPECT_FALSE(validate_motion(three_keys()));
  ScriptedMotion s = spinning();
  s.initial.position.y() = kNaN;
  EXPECT_EQ(validate_motion(s)->message,
            "initial position has a non-finite coordinate (0.3, nan, -0.4)");
  s = spinning();
  s.initial.rotation = Quat(0, 0, 0, 0);
  EXPECT_EQ(validate_motion(s)->message, "initial rotation is the zero quaternion");
  s.initial.rotation = Quat(2, 0, 0, 0);
  EXPECT_EQ(validate_motion(s)->message, "initial rotation is not a unit quaternion (norm 2)");
  s.initial.rotation = Quat(kNaN, 0, 0, 0);
  EXPECT_EQ(validate_motion(s)->message, "initial rotation has a non-finite component");
  s = spinning();
  s.angular_velocity.z() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validate_motion(s)->message,
            "angular velocity has a non-finite coordinate (-0.4, 1.1, inf)");

  EXPECT_EQ(validate_motion(KeyframedMotion{})->message, "keyframed motion has no keyframes");
  KeyframedMotion k = three_keys();
  k.keyframes[2].time = 1.5;
  EXPECT_EQ(validate_motion(k)->message, "keyframe 2 is at 1.5 s, not after keyframe 1 at 1.5 s");
  k = three_keys();
  k.keyframes[1].time = kNaN;
  EXPECT_EQ(validate_motion(k)->message, "keyframe 1 has a non-finite time");
  k = three_keys();
  k.keyframes[0].rotation = Quat(0.5, 0.5, 0.5, 0.0);
  EXPECT_EQ(validate_motion(k)->message,
            "keyframe 0 rotation is not a unit quaternion (norm 0.866025)");
}

}  // namespace
}  // namespace animkit
