#include "animkit/collision/collider_motion.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "animkit/core/validation.h"

namespace animkit {

namespace {
std::optional<Error> check_rotation(const Quat& q, const std::string& what) {
  if (!is_finite(q)) return Error{what + " has a non-finite component"};
  const double norm = q.norm();
  if (norm == 0.0) return Error{what + " is the zero quaternion"};
  if (std::abs(norm - 1.0) > kUnitTolerance) {
    return Error{what + " is not a unit quaternion (norm " + format_number(norm) + ")"};
  }
  return std::nullopt;
}

std::optional<Error> check_vector(const Vec3& v, const std::string& what,
                                  const ParameterRange& range) {
  if (!is_finite(v)) return Error{what + " has a non-finite coordinate " + to_string(v)};
  if (!range.contains(v)) return Error{range.refusal(what, v)};
  return std::nullopt;
}

// The rotation from keyframe a's orientation to b's along the shorter arc, in world axes
// (q_b q_a^-1, with q_b negated when that shortens the arc): its angle is in [0, pi].
Eigen::AngleAxisd segment_turn(const Keyframe& a, const Keyframe& b) {
  Quat qb = b.rotation.normalized();
  const Quat qa = a.rotation.normalized();
  if (qa.dot(qb) < 0.0) qb.coeffs() = -qb.coeffs();
  return Eigen::AngleAxisd(qb * qa.conjugate());
}

RigidPose keyframe_pose(const Keyframe& k) {
  return {k.position, k.rotation.normalized()};
}

// Index of the segment [keys[i], keys[i + 1]) holding t, for t strictly inside the keyframes'
// time span.
std::size_t segment_index(const std::vector<Keyframe>& keys, double t) {
  const auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                      [](double time, const Keyframe& k) { return time < k.time; });
  return static_cast<std::size_t>(after - keys.begin()) - 1;
}

// The frame's velocity: linear (of its origin) and angular, world space.
struct FrameVelocity {
  Vec3 linear = Vec3::Zero(), angular = Vec3::Zero();
};

FrameVelocity frame_velocity(const ScriptedMotion& m, double) {
  return {m.linear_velocity, m.angular_velocity};
}

FrameVelocity frame_velocity(const KeyframedMotion& m, double t) {
  const auto& keys = m.keyframes;
  if (keys.empty() || t < keys.front().time || t >= keys.back().time) return {};
  const std::size_t i = segment_index(keys, t);
  const Keyframe& a = keys[i];
  const Keyframe& b = keys[i + 1];
  const double duration = b.time - a.time;
  const Eigen::AngleAxisd turn = segment_turn(a, b);
  return {(b.position - a.position) / duration, turn.axis() * (turn.angle() / duration)};
}

RigidPose pose_of(const ScriptedMotion& m, double t) {
  RigidPose pose{m.initial.position + m.linear_velocity * t, m.initial.rotation.normalized()};
  const double speed = m.angular_velocity.norm();
  if (speed > 0.0) {
    pose.rotation = Quat(Eigen::AngleAxisd(speed * t, m.angular_velocity / speed)) * pose.rotation;
  }
  return pose;
}

RigidPose pose_of(const KeyframedMotion& m, double t) {
  const auto& keys = m.keyframes;
  if (keys.empty()) return {};
  if (t <= keys.front().time) return keyframe_pose(keys.front());
  if (t >= keys.back().time) return keyframe_pose(keys.back());
  const std::size_t i = segment_index(keys, t);
  const Keyframe& a = keys[i];
  const Keyframe& b = keys[i + 1];
  const double s = (t - a.time) / (b.time - a.time);
  // Slerp written as a partial turn, q(s) = exp(s log(q_b q_a^-1)) q_a: the same rotation as
  // Eigen's slerp, and its derivative is exactly the angular velocity frame_velocity() gives.
  const Eigen::AngleAxisd turn = segment_turn(a, b);
  const Quat partial(Eigen::AngleAxisd(s * turn.angle(), turn.axis()));
  return {a.position + s * (b.position - a.position), partial * a.rotation.normalized()};
}

std::optional<Error> validate(const ScriptedMotion& m) {
  if (auto e = check_vector(m.initial.position, "initial position", kCoordinateRange)) return e;
  if (auto e = check_rotation(m.initial.rotation, "initial rotation")) return e;
  if (auto e = check_vector(m.linear_velocity, "linear velocity", kSpeedRange)) return e;
  return check_vector(m.angular_velocity, "angular velocity", kAngularSpeedRange);
}

std::optional<Error> validate(const KeyframedMotion& m) {
  if (m.keyframes.empty()) return Error{"keyframed motion has no keyframes"};
  for (std::size_t i = 0; i < m.keyframes.size(); ++i) {
    const Keyframe& k = m.keyframes[i];
    const std::string name = "keyframe " + std::to_string(i);
    if (!std::isfinite(k.time)) return Error{name + " has a non-finite time"};
    if (!kTimeRange.contains(k.time)) return Error{kTimeRange.refusal(name + " time (s)", k.time)};
    if (auto e = check_vector(k.position, name + " position", kCoordinateRange)) return e;
    if (auto e = check_rotation(k.rotation, name + " rotation")) return e;
    if (i > 0 && !(k.time > m.keyframes[i - 1].time)) {
      return Error{name + " is at " + format_number(k.time) + " s, not after keyframe " +
                   std::to_string(i - 1) + " at " + format_number(m.keyframes[i - 1].time) + " s"};
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<Error> validate_motion(const ColliderMotion& motion) {
  return std::visit([](const auto& m) { return validate(m); }, motion);
}

std::optional<Error> validate_pose(const RigidPose& pose) {
  if (auto e = check_vector(pose.position, "position", kCoordinateRange)) return e;
  return check_rotation(pose.rotation, "rotation");
}

bool moves(const ColliderMotion& motion) {
  if (const auto* scripted = std::get_if<ScriptedMotion>(&motion))
    return !scripted->linear_velocity.isZero(0.0) || !scripted->angular_velocity.isZero(0.0);
  const auto& keys = std::get<KeyframedMotion>(motion).keyframes;
  for (std::size_t i = 1; i < keys.size(); ++i) {
    const Eigen::Vector4d q = keys[i].rotation.coeffs(), q0 = keys[0].rotation.coeffs();
    // q and -q are the same rotation.
    if (keys[i].position != keys[0].position || (q != q0 && q != -q0)) return true;
  }
  return false;
}

RigidPose pose_at(const ColliderMotion& motion, double t) {
  return std::visit([t](const auto& m) { return pose_of(m, t); }, motion);
}

Vec3 point_velocity(const ColliderMotion& motion, double t, const Vec3& world_point) {
  const RigidPose pose = pose_at(motion, t);
  const FrameVelocity v = std::visit([t](const auto& m) { return frame_velocity(m, t); }, motion);
  return v.linear + v.angular.cross(world_point - pose.position);
}

}  // namespace animkit
